!> Tests of `&linkage` decks (any planar linkage of lower pairs): the structural analysis of the
!> bundled decks and of wrong decks; velocities and accelerations (class-III group, two
!> drives, sliding pairs on the frame and on moving links, stroke drives) against central
!> finite differences of the positions; the
!> reactions' self-checks (every link's equilibrium, the power balance of every drive, the
!> Lagrange multipliers against the group method's free bodies, and a wrong mass in either
!> caught); the branch kept through a full turn; a dead
!> position of the class-III group found (exit 3 naming the group).
module test_linkage
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: int_str, real_str
  use kinetostat_error, only: error_t, exit_geometry, exit_input
  use kinetostat_deck, only: deck_source_t, load_deck, deck_source_from_text
  use kinetostat_linkage, only: linkage_t, linkage_step_t, linkage_reference_pose, linkage_assemble, linkage_motion, &
    linkage_work_t, linkage_free_body, linkage_reaction_gap, linkage_statics, linkage_assemble_newton
  use kinetostat_linkage_structure, only: structure_formula
  use kinetostat_linkage_deck, only: linkage_deck_t, read_linkage_deck, linkage_drive_values, linkage_load_value
  use kinetostat_linkage_layout, only: linkage_solve_steps
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_linkage_tests

  !> Every bundled &linkage deck (data/ and the examples of docs/linkage.md).
  character(len=*), parameter :: linkage_decks(6) = [character(len=32) :: "data/class3.nml", "data/fivebar.nml", &
    "data/linkage_fourbar.nml", "data/linkage_slider_crank.nml", "docs/examples/excavator.nml", &
    "docs/examples/class3_order4.nml"]

contains

  subroutine run_linkage_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_structure(t)
    call test_wrong_structures(t)
    call test_finite_differences(t)
    call test_reactions(t)
    call test_second_opinion(t)
    call test_full_turn(t)
    call test_dead_position(t)
    call test_closed_forms(t)
  end subroutine run_linkage_tests

  !> A bundled deck, read and validated.
  subroutine bundled(path, deck, t)
    character(*), intent(in) :: path
    type(linkage_deck_t), intent(out) :: deck
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    call load_deck(path, source, error)
    if (.not. allocated(error)) call read_linkage_deck(source, deck, error)
    call check_true(t, "linkage-read-"//path, .not. allocated(error), "deck error")
    if (allocated(error)) write (*, '(a)') "  "//error%message
  end subroutine bundled

  !> Steps 1..last of a deck solved from its reference pose, as a run's first block starts.
  subroutine solve_from_reference(deck, name, last, steps, error)
    type(linkage_deck_t), intent(in) :: deck
    !> The deck's name in messages.
    character(*), intent(in) :: name
    !> Last step solved.
    integer, intent(in) :: last
    type(linkage_step_t), allocatable, intent(out) :: steps(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp), allocatable :: q(:), from(:)
    allocate (q, source=linkage_reference_pose(deck%mech))
    allocate (from(size(deck%mech%drives)))
    from(:) = deck%mech%drives%q_ref
    allocate (steps(last))
    call linkage_solve_steps(deck, name, 1, last, q, from, steps, error)
  end subroutine solve_from_reference

  !> Known structure formulas and classes of the bundled decks.
  subroutine test_structure(t)
    type(test_counts_t), intent(inout) :: t
    type(linkage_deck_t) :: deck
    character(len=*), parameter :: paths(4) = [character(len=32) :: "data/class3.nml", "data/fivebar.nml", &
      "data/linkage_fourbar.nml", "data/linkage_slider_crank.nml"]
    character(len=*), parameter :: formulas(4) = [character(len=40) :: "I(0,1) -> III(2,3,4,5)", &
      "I(0,1) -> I(0,4) -> II(2,3)", "I(0,1) -> II(2,3)", "I(0,1) -> II(2,3)"]
    character(len=3), parameter :: kinds(4) = ["   ", "RRR", "RRR", "RRP"]
    integer :: i, last
    do i = 1, size(paths)
      call bundled(trim(paths(i)), deck, t)
      call check_true(t, "linkage-structure-"//trim(paths(i)), structure_formula(deck%mech) == trim(formulas(i)), &
        "expected '"//trim(formulas(i))//"', got '"//structure_formula(deck%mech)//"'")
      last = size(deck%mech%units)
      call check_true(t, "linkage-group-kind-"//trim(paths(i)), deck%mech%units(last)%kind == kinds(i), &
        "expected kind '"//kinds(i)//"', got '"//deck%mech%units(last)%kind//"'")
    end do
    call bundled("data/class3.nml", deck, t)
    call check_true(t, "linkage-class3-order", deck%mech%units(2)%class == 3 .and. deck%mech%units(2)%order == 3, &
      "expected class 3, order 3; got class "//int_str(deck%mech%units(2)%class)//", order "// &
      int_str(deck%mech%units(2)%order))
    call bundled("docs/examples/class3_order4.nml", deck, t)
    call check_true(t, "linkage-class3-order4", structure_formula(deck%mech) == "I(0,1) -> III(2,3,4,5,6,7)" .and. &
      deck%mech%units(2)%class == 3 .and. deck%mech%units(2)%order == 4, &
      "expected I(0,1) -> III(2,3,4,5,6,7), class 3, order 4; got "//structure_formula(deck%mech)//", class "// &
      int_str(deck%mech%units(2)%class)//", order "//int_str(deck%mech%units(2)%order))
  end subroutine test_structure

  !> The four-bar deck text with extra lines (links, pairs, drives) appended before the end.
  function fourbar_text(extra) result(text)
    character(*), intent(in) :: extra
    character(len=:), allocatable :: text
    character(len=*), parameter :: nl = achar(10)
    text = "&linkage"//nl//"n = 3"//nl// &
      "link(1)%id = 1, link(2)%id = 2, link(3)%id = 3"//nl// &
      "pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0"//nl// &
      "pair(2)%name = 'B', pair(2)%kind = 'R', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0"//nl// &
      "pair(3)%name = 'C', pair(3)%kind = 'R', pair(3)%links = 3, 2, pair(3)%at = 0.4, 0.2"//nl// &
      "pair(4)%name = 'D', pair(4)%kind = 'R', pair(4)%links = 3, 0, pair(4)%at = 0.3, 0"//nl// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 10, drive(1)%omega = 1"//nl//extra//nl//"/"//nl
  end function fourbar_text

  !> Wrong decks: W /= drives (missing and surplus constraints), a set of links that is no
  !> group (a link over-constrained while another is free).
  subroutine test_wrong_structures(t)
    type(test_counts_t), intent(inout) :: t
    call expect_error("linkage-w-missing", "link(4)%id = 4"//achar(10)// &
      "pair(5)%name = 'E', pair(5)%kind = 'R', pair(5)%links = 4, 3, pair(5)%at = 0.5, 0.3", &
      "W = 3n - 2p5 = 3 x 4 - 2 x 5 = 2 but 1 drive(s): 1 constraint(s) missing")
    call expect_error("linkage-w-surplus", "drive(2)%pair = 'D', drive(2)%start = 0, drive(2)%step = 1, "// &
      "drive(2)%omega = 1", "W = 3n - 2p5 = 3 x 3 - 2 x 4 = 1 but 2 drive(s): 1 surplus constraint(s)")
    call expect_error("linkage-not-a-group", "link(4)%id = 4, link(5)%id = 5"//achar(10)// &
      "pair(5)%name = 'E', pair(5)%kind = 'R', pair(5)%links = 4, 0, pair(5)%at = 0.5, 0.5"//achar(10)// &
      "pair(6)%name = 'F', pair(6)%kind = 'R', pair(6)%links = 4, 3, pair(6)%at = 0.35, 0.1"//achar(10)// &
      "pair(7)%name = 'G', pair(7)%kind = 'R', pair(7)%links = 5, 0, pair(7)%at = 0.9, 0.9", &
      "links 4 have 1 surplus constraint(s)")
  contains
    subroutine expect_error(name, extra, expected)
      character(*), intent(in) :: name, extra, expected
      type(deck_source_t) :: source
      type(linkage_deck_t) :: deck
      type(error_t), allocatable :: error
      call deck_source_from_text("wrong.nml", fourbar_text(extra), source)
      call read_linkage_deck(source, deck, error)
      if (.not. allocated(error)) then
        call check_true(t, name, .false., "no error; expected '"//expected//"'")
        return
      end if
      call check_true(t, name, error%code == exit_input .and. index(error%message, expected) > 0, &
        "expected exit 2 with '"//expected//"', got exit "//int_str(error%code)//": "//error%message)
    end subroutine expect_error
  end subroutine test_wrong_structures

  !> Velocities and accelerations against central differences of the positions along the
  !> drives' motion q(t) with drive(t) = q0 + v t + a t^2 / 2 (each drive with its own speed
  !> and a non-zero acceleration): dq/dt and d2q/dt2 at t = 0. Half step: the fastest drive moves
  !> 2e-4 (rad or m); tolerance 1e-6 of the largest |qd| (velocities) and 1e-5 of the largest |qdd|
  !> (accelerations) plus the differences' roundoff.
  subroutine test_finite_differences(t)
    type(test_counts_t), intent(inout) :: t
    call fd_deck("data/class3.nml", [10, 14, 25])
    call fd_deck("data/fivebar.nml", [3, 20, 33])
    call fd_deck("data/linkage_slider_crank.nml", [2, 6, 11])
    call fd_deck("docs/examples/excavator.nml", [1, 9, 20])
  contains
    subroutine fd_deck(path, ks)
      character(*), intent(in) :: path
      integer, intent(in) :: ks(:)
      type(linkage_deck_t) :: deck
      type(linkage_step_t), allocatable :: steps(:)
      type(error_t), allocatable :: error
      real(wp), allocatable :: dq(:), dv(:), da(:), qp(:), qm(:), qd(:), qdd(:), fd1(:), fd2(:)
      type(linkage_work_t) :: work
      real(wp) :: h, tol1, tol2
      integer :: i, j, k, nd
      call bundled(path, deck, t)
      nd = size(deck%mech%drives)
      allocate (dq(nd), dv(nd), da(nd))
      call solve_from_reference(deck, path, maxval(ks), steps, error)
      call check_true(t, "linkage-fd-solve-"//path, .not. allocated(error), "solve failed")
      if (allocated(error)) return
      do i = 1, size(ks)
        k = ks(i)
        call linkage_drive_values(deck, k, dq, dv, da)
        do j = 1, nd
          da(j) = 0.7_wp * real((-1)**j, wp) * maxval(abs(dv))
        end do
        allocate (qd(size(steps(k)%q)), qdd(size(steps(k)%q)))
        call linkage_motion(deck%mech, steps(k)%q, dv, da, qd, qdd, work, error)
        h = 2.0e-4_wp / maxval(abs(dv))
        qp = steps(k)%q
        qm = steps(k)%q
        call linkage_assemble(deck%mech, dq, dq + dv * h + 0.5_wp * da * h**2, qp, work, error)
        if (.not. allocated(error)) call linkage_assemble(deck%mech, dq, dq - dv * h + 0.5_wp * da * h**2, qm, work, error)
        call check_true(t, "linkage-fd-assemble-"//path, .not. allocated(error), "assembly failed")
        if (allocated(error)) return
        fd1 = (qp - qm) / (2.0_wp * h)
        fd2 = (qp - 2.0_wp * steps(k)%q + qm) / h**2
        tol1 = 1.0e-6_wp * maxval(abs(qd))
        tol2 = 1.0e-5_wp * maxval(abs(qdd)) + 1.0e-12_wp / h**2
        call check_true(t, "linkage-fd-velocity-"//path//"-step"//int_str(k), maxval(abs(fd1 - qd)) <= tol1, &
          "max |FD - qd| = "//real_str(maxval(abs(fd1 - qd)))//" > "//real_str(tol1))
        call check_true(t, "linkage-fd-acceleration-"//path//"-step"//int_str(k), maxval(abs(fd2 - qdd)) <= tol2, &
          "max |FD - qdd| = "//real_str(maxval(abs(fd2 - qdd)))//" > "//real_str(tol2))
        deallocate (qd, qdd)
      end do
    end subroutine fd_deck
  end subroutine test_finite_differences

  !> Every step of every bundled &linkage deck: equilibrium residual and power mismatch of
  !> every drive <= 1e-9, the Lagrange and the group method's reactions within 1e-12 of the step's
  !> largest reaction.
  subroutine test_reactions(t)
    type(test_counts_t), intent(inout) :: t
    type(linkage_deck_t) :: deck
    type(linkage_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    integer :: i
    do i = 1, size(linkage_decks)
      call bundled(trim(linkage_decks(i)), deck, t)
      call solve_from_reference(deck, trim(linkage_decks(i)), deck%n, steps, error)
      call check_true(t, "linkage-solve-"//trim(linkage_decks(i)), .not. allocated(error), "solve failed")
      if (allocated(error)) cycle
      call check_true(t, "linkage-residual-"//trim(linkage_decks(i)), maxval(steps%residual) <= 1.0e-9_wp, &
        "max residual "//real_str(maxval(steps%residual)))
      call check_true(t, "linkage-power-"//trim(linkage_decks(i)), maxval(steps%mismatch) <= 1.0e-9_wp, &
        "max power mismatch "//real_str(maxval(steps%mismatch)))
      call check_true(t, "linkage-two-solvers-"//trim(linkage_decks(i)), maxval(steps%solver_gap) <= 1.0e-12_wp, &
        "max gap of the Lagrange and the group method's reactions "//real_str(maxval(steps%solver_gap))//" > 1e-12")
    end do
  end subroutine test_reactions

  !> The second opinion is independent and can fail: on every bundled &linkage deck at every
  !> step the group method's free bodies give the Lagrange form's reactions within 1e-9 of
  !> the step's largest reaction; with one link's mass 1 % wrong in the group method only
  !> (each link with a mass in turn), or in the Lagrange form only (the heaviest link), the
  !> gap exceeds 1e-9 at some step.
  subroutine test_second_opinion(t)
    type(test_counts_t), intent(inout) :: t
    type(linkage_deck_t) :: deck
    type(linkage_t) :: wrong
    type(linkage_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    real(wp) :: gap
    integer :: i, j, heavy
    do i = 1, size(linkage_decks)
      call bundled(trim(linkage_decks(i)), deck, t)
      call solve_from_reference(deck, trim(linkage_decks(i)), deck%n, steps, error)
      if (allocated(error)) then
        call check_true(t, "linkage-second-opinion-solve-"//trim(linkage_decks(i)), .false., error%message)
        cycle
      end if
      gap = max_gap(deck, deck%mech, steps)
      call check_true(t, "linkage-second-opinion-"//trim(linkage_decks(i)), gap <= 1.0e-9_wp, &
        "max gap of the two formulations "//real_str(gap)//" > 1e-9")
      ! a wrong mass in the group method
      do j = 1, size(deck%mech%links)
        if (deck%mech%links(j)%m <= 0.0_wp) cycle
        wrong = deck%mech
        wrong%links(j)%m = 1.01_wp * wrong%links(j)%m
        gap = max_gap(deck, wrong, steps)
        call check_true(t, "linkage-second-opinion-catches-mass-"//trim(linkage_decks(i))//"-link"// &
          int_str(deck%mech%links(j)%id), &
          gap > 1.0e-9_wp, "a 1 % wrong mass in the group method gives a gap of only "//real_str(gap))
      end do
      ! a wrong mass in the Lagrange form: its steps again, the group method with the right one
      heavy = maxloc(deck%mech%links%m, 1)
      wrong = deck%mech
      wrong%links(heavy)%m = 1.01_wp * wrong%links(heavy)%m
      call restatics(deck, wrong, steps)
      gap = max_gap(deck, deck%mech, steps)
      call check_true(t, "linkage-second-opinion-catches-lagrange-mass-"//trim(linkage_decks(i)), gap > 1.0e-9_wp, &
        "a 1 % wrong mass in the Lagrange form gives a gap of only "//real_str(gap))
    end do
  contains
    !> Largest gap over the steps of their reactions and the group method's with linkage `mech`.
    real(wp) function max_gap(deck, mech, steps) result(gap)
      type(linkage_deck_t), intent(in) :: deck
      type(linkage_t), intent(in) :: mech
      type(linkage_step_t), intent(in) :: steps(:)
      type(linkage_work_t) :: work
      type(error_t), allocatable :: error
      real(wp), allocatable :: fval(:), mval(:), f(:, :), normal(:), couple(:), effort(:)
      integer :: k
      allocate (f(2, size(mech%pairs)), normal(size(mech%pairs)), couple(size(mech%pairs)), &
                effort(size(mech%drives)))
      gap = 0.0_wp
      do k = 1, size(steps)
        call load_values(deck, k, fval, mval)
        call linkage_free_body(mech, fval, mval, steps(k), work, f, normal, couple, effort, error)
        if (allocated(error)) then
          gap = huge(1.0_wp)
          return
        end if
        gap = max(gap, linkage_reaction_gap(mech, steps(k), f, normal, couple, effort))
      end do
    end function max_gap
    !> The steps' reactions again (the Lagrange form) with linkage `mech`.
    subroutine restatics(deck, mech, steps)
      type(linkage_deck_t), intent(in) :: deck
      type(linkage_t), intent(in) :: mech
      type(linkage_step_t), intent(inout) :: steps(:)
      type(linkage_work_t) :: work
      type(error_t), allocatable :: error
      real(wp), allocatable :: fval(:), mval(:)
      integer :: k
      do k = 1, size(steps)
        call load_values(deck, k, fval, mval)
        deallocate (steps(k)%f, steps(k)%normal, steps(k)%couple, steps(k)%effort)
        call linkage_statics(mech, fval, mval, steps(k), work, error)
        if (allocated(error)) return
      end do
    end subroutine restatics
    !> The force magnitudes and moments of step k.
    subroutine load_values(deck, k, fval, mval)
      type(linkage_deck_t), intent(in) :: deck
      integer, intent(in) :: k
      real(wp), allocatable, intent(out) :: fval(:), mval(:)
      integer :: m
      allocate (fval(size(deck%force_load)), mval(size(deck%moment_load)))
      do m = 1, size(fval)
        fval(m) = linkage_load_value(deck, deck%force_load(m), k)
      end do
      do m = 1, size(mval)
        mval(m) = linkage_load_value(deck, deck%moment_load(m), k)
      end do
    end subroutine load_values
  end subroutine test_second_opinion

  !> The class-III deck turns its crank once (37 steps of 10 deg): the last step's poses and
  !> forces equal the first's (the branch of the reference position is kept), 1e-9.
  subroutine test_full_turn(t)
    type(test_counts_t), intent(inout) :: t
    type(linkage_deck_t) :: deck
    type(linkage_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    real(wp), allocatable :: d(:)
    call bundled("data/class3.nml", deck, t)
    call solve_from_reference(deck, "class3", deck%n, steps, error)
    if (allocated(error)) then
      call check_true(t, "linkage-full-turn", .false., error%message)
      return
    end if
    allocate (d(size(steps(1)%q)))
    d(:) = steps(deck%n)%q - steps(1)%q
    d(3::3) = modulo(d(3::3) + 3.0_wp, 6.283185307179586_wp) - 3.0_wp
    call check_true(t, "linkage-full-turn-poses", maxval(abs(d)) <= 1.0e-9_wp, "max pose change "//real_str(maxval(abs(d))))
    call check_close(t, "linkage-full-turn-F54", norm2(steps(1)%f(:, 7)), norm2(steps(deck%n)%f(:, 7)), 1.0e-9_wp, 1.0e-9_wp)
    call check_close(t, "linkage-full-turn-M1", steps(1)%effort(1), steps(deck%n)%effort(1), 1.0e-9_wp, 1.0e-9_wp)
  end subroutine test_full_turn

  !> The class-III deck with its pivot C moved up to (0.641, -0.35): link 4 is shorter and the
  !> group cannot follow the crank through a whole turn; the run stops with exit 3 naming the
  !> step and the group III(2,3,4,5).
  subroutine test_dead_position(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(linkage_deck_t) :: deck
    type(linkage_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    call load_deck("data/class3.nml", source, error)
    if (.not. allocated(error)) then
      source%records(size(source%records)) = " pair(6)%at = 0.641, -0.35 /"
      call read_linkage_deck(source, deck, error)
    end if
    call check_true(t, "linkage-dead-deck", .not. allocated(error), "deck error")
    if (allocated(error)) then
      write (*, '(a)') "  "//error%message
      return
    end if
    call solve_from_reference(deck, "dead", deck%n, steps, error)
    if (.not. allocated(error)) then
      call check_true(t, "linkage-dead-position", .false., "no error")
      return
    end if
    call check_true(t, "linkage-dead-position", error%code == exit_geometry .and. &
      index(error%message, "group III(2,3,4,5)") > 0 .and. index(error%message, "step ") > 0, &
      "expected exit 3 naming the step and group III(2,3,4,5), got exit "//int_str(error%code)//": "//error%message)
  end subroutine test_dead_position

  !> The closed forms of the dyads and input units against Newton's method (a second,
  !> independent solve, here converged to 1e-14 of the linkage's size): two continuations
  !> from the reference pose, one by each, over every step of every bundled &linkage deck
  !> whose units all have closed forms and of four decks with the other dyad kinds (RPR,
  !> PRP, RPP, and RRP with its guide on the crank), then over 40 random drive values within the run's range: every pose within
  !> 1e-12 of the linkage's size (so the same branch throughout), and the closed forms in use.
  !> Both assembly branches: the four-bar crossed and the slider-crank with its slider on
  !> the other side. At every step the fast path (velocities, accelerations and the reactions
  !> from the points and the dyads' closed forms, no J: every unit of every step) against the
  !> general solve (J by LU, the Lagrange multipliers): within 1e-12 of the step's largest
  !> value. On every step of every deck the two formulations agree: the group method's
  !> reactions within 1e-9 of the step's largest reaction of the Lagrange multipliers' (by
  !> the closed forms and by LU), every link's equilibrium residual <= 1e-12 (the PRP and
  !> RRP decks' cranks, loaded by a sliding pair of the dyad, once differed by 0.81 and
  !> 0.33).
  subroutine test_closed_forms(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: decks(5) = [character(len=40) :: "data/fivebar.nml", "data/linkage_fourbar.nml", &
      "data/linkage_slider_crank.nml", "data/linkage_engine.nml", "data/linkage_pr3207_flywheel.nml"]
    type(linkage_deck_t) :: deck
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    !> The closed-form solves against the general ones at the same poses (compare's): the
    !> largest differences of the velocities, accelerations (relative to the step's largest),
    !> reactions by the multipliers and by the group method (relative to the step's largest
    !> reaction); the unit solves made in closed form.
    real(wp) :: worst_v, worst_a, worst_lam, worst_fb
    !> The largest gap of the group method's reactions and the multipliers' (relative to the
    !> step's largest reaction), and the largest equilibrium residual of a link (relative).
    real(wp) :: worst_gap, worst_res
    integer :: i, small
    do i = 1, size(decks)
      call bundled(trim(decks(i)), deck, t)
      call compare(trim(decks(i)), deck)
    end do
    ! RPR: crank 1 (A-B), block 2 on it at B sliding in the slot of rocker 3 (pivot C)
    call from_text("rpr", "link(1)%id = 1, link(1)%m = 1, link(1)%j = 0.01, link(1)%s = 0.05, 0 "// &
      "link(2)%id = 2, link(2)%m = 0.5, link(2)%j = 0.001, link(2)%s = 0.1, 0 "// &
      "link(3)%id = 3, link(3)%m = 2, link(3)%j = 0.05, link(3)%s = 0.2, 0.025 "// &
      "pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0 "// &
      "pair(2)%name = 'B', pair(2)%kind = 'R', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0 "// &
      "pair(3)%name = 'T', pair(3)%kind = 'P', pair(3)%links = 2, 3, pair(3)%at = 0.1, 0, pair(3)%guide = 3, "// &
      "pair(3)%angle = 194.03624346792648 "// &
      "pair(4)%name = 'C', pair(4)%kind = 'R', pair(4)%links = 3, 0, pair(4)%at = 0.3, 0.05 "// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 10, drive(1)%omega = 10")
    ! PRP: block 2 sliding along crank 1, pinned at D to slider 3 on the frame's vertical guide
    call from_text("prp", "link(1)%id = 1, link(1)%m = 1, link(1)%j = 0.01, link(1)%s = 0.05, 0 "// &
      "link(2)%id = 2, link(2)%m = 0.5, link(2)%j = 0.001, link(2)%s = 0.1, 0 "// &
      "link(3)%id = 3, link(3)%m = 2, link(3)%j = 0, link(3)%s = 0.1, 0.02 "// &
      "pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0 "// &
      "pair(2)%name = 'B', pair(2)%kind = 'P', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0, pair(2)%guide = 1, "// &
      "pair(2)%angle = 0 "// &
      "pair(3)%name = 'D', pair(3)%kind = 'R', pair(3)%links = 2, 3, pair(3)%at = 0.1, 0 "// &
      "pair(4)%name = 'E', pair(4)%kind = 'P', pair(4)%links = 3, 0, pair(4)%at = 0.1, 0.05, pair(4)%guide = 0, "// &
      "pair(4)%angle = 90 "// &
      "drive(1)%pair = 'A', drive(1)%start = -40, drive(1)%step = 10, drive(1)%omega = 10")
    ! RPP: the Scotch yoke: block 2 pinned to crank 1 at B, sliding in the vertical slot of
    ! yoke 3, which slides on the frame's horizontal guide
    call from_text("rpp", "link(1)%id = 1, link(1)%m = 1, link(1)%j = 0.01, link(1)%s = 0.05, 0 "// &
      "link(2)%id = 2, link(2)%m = 0.5, link(2)%j = 0.001, link(2)%s = 0.1, 0 "// &
      "link(3)%id = 3, link(3)%m = 2, link(3)%j = 0.02, link(3)%s = 0.15, 0 "// &
      "pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0 "// &
      "pair(2)%name = 'B', pair(2)%kind = 'R', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0 "// &
      "pair(3)%name = 'S', pair(3)%kind = 'P', pair(3)%links = 2, 3, pair(3)%at = 0.1, 0, pair(3)%guide = 3, "// &
      "pair(3)%angle = 90 "// &
      "pair(4)%name = 'E', pair(4)%kind = 'P', pair(4)%links = 3, 0, pair(4)%at = 0.2, 0, pair(4)%guide = 0, "// &
      "pair(4)%angle = 0 "// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 10, drive(1)%omega = 10")
    ! RRP with the guide on the crank: block 2 sliding along crank 1, pinned at C to rocker 3
    ! (pivot D); the crank carries the dyad's sliding pair
    call from_text("rrp-guide-on-crank", "link(1)%id = 1, link(1)%m = 1, link(1)%j = 0.01, link(1)%s = 0.05, 0 "// &
      "link(2)%id = 2, link(2)%m = 0.5, link(2)%j = 0.001, link(2)%s = 0.1, 0 "// &
      "link(3)%id = 3, link(3)%m = 2, link(3)%j = 0.02, link(3)%s = 0.15, 0.05 "// &
      "pair(1)%name = 'A', pair(1)%kind = 'R', pair(1)%links = 1, 0, pair(1)%at = 0, 0 "// &
      "pair(2)%name = 'B', pair(2)%kind = 'P', pair(2)%links = 2, 1, pair(2)%at = 0.1, 0, pair(2)%guide = 1, "// &
      "pair(2)%angle = 0 "// &
      "pair(3)%name = 'C', pair(3)%kind = 'R', pair(3)%links = 2, 3, pair(3)%at = 0.1, 0 "// &
      "pair(4)%name = 'D', pair(4)%kind = 'R', pair(4)%links = 3, 0, pair(4)%at = 0.2, 0.1 "// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 1.5, drive(1)%omega = 10")
    ! the other assembly branches: the four-bar with C mirrored across B-D (crossed), the
    ! slider-crank with its slider on the other side of the crank's pivot
    call from_text("fourbar-other-branch", "link(1)%id = 1, link(1)%m = 0.5, link(1)%j = 0.002, "// &
      "link(1)%s = 0.038302222155948904, 0.032139380484326963 "// &
      "link(2)%id = 2, link(2)%m = 1.0, link(2)%j = 0.0102, link(2)%s = 0.15994577290272566, -0.08960178669321153 "// &
      "link(3)%id = 3, link(3)%m = 0.8, link(3)%j = 0.0042, link(3)%s = 0.2716435507467767, -0.1217411671775385 "// &
      "pair(1)%name = 'B', pair(1)%kind = 'R', pair(1)%links = 2, 1, pair(1)%at = 0.076604444311897807, "// &
      "0.064278760968653925 "// &
      "pair(2)%name = 'C', pair(2)%kind = 'R', pair(2)%links = 2, 3, pair(2)%at = 0.24328710149355348, "// &
      "-0.243482334355077 "// &
      "pair(3)%name = 'D', pair(3)%kind = 'R', pair(3)%links = 3, 0, pair(3)%at = 0.3, 0 "// &
      "pair(4)%name = 'A', pair(4)%kind = 'R', pair(4)%links = 1, 0, pair(4)%at = 0, 0 "// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 10, drive(1)%omega = 20 "// &
      "force(1)%link = 2, force(1)%at = 0.2, -0.1, force(1)%angle = 30, force(1)%follow = .true., "// &
      "force(1)%value = 50 moment(1)%link = 3, moment(1)%value = -20")
    call from_text("slider-crank-other-branch", "link(1)%id = 1, link(1)%m = 2.0, link(1)%j = 0.01, link(1)%s = 0, 0 "// &
      "link(2)%id = 2, link(2)%m = 1.5, link(2)%j = 0.02, link(2)%s = -0.07471405209656148, 0.01 "// &
      "link(3)%id = 3, link(3)%m = 3.0, link(3)%j = 0, link(3)%s = -0.24942810419312297, 0.02 "// &
      "pair(1)%name = 'B', pair(1)%kind = 'R', pair(1)%links = 2, 1, pair(1)%at = 0.1, 0 "// &
      "pair(2)%name = 'C', pair(2)%kind = 'R', pair(2)%links = 2, 3, pair(2)%at = -0.24942810419312297, 0.02 "// &
      "pair(3)%name = 'D', pair(3)%kind = 'P', pair(3)%links = 3, 0, pair(3)%at = -0.24942810419312297, 0.02, "// &
      "pair(3)%angle = 0, pair(3)%guide = 0 "// &
      "pair(4)%name = 'A', pair(4)%kind = 'R', pair(4)%links = 1, 0, pair(4)%at = 0, 0 "// &
      "drive(1)%pair = 'A', drive(1)%start = 0, drive(1)%step = 10, drive(1)%omega = 50 "// &
      "force(1)%link = 3, force(1)%at = -0.24942810419312297, 0.02, force(1)%angle = 0, force(1)%value = 500")
  contains
    subroutine from_text(name, body)
      character(*), intent(in) :: name, body
      call deck_source_from_text(name//".nml", "&linkage title = '"//name//"' frame = 0 n = 37 "//body//" /", source)
      call read_linkage_deck(source, deck, error)
      call check_true(t, "linkage-closed-read-"//name, .not. allocated(error), "deck error")
      if (allocated(error)) then
        write (*, '(a)') "  "//error%message
        return
      end if
      call compare(name, deck)
    end subroutine from_text
    subroutine compare(name, deck)
      character(*), intent(in) :: name
      type(linkage_deck_t), intent(in) :: deck
      type(linkage_work_t) :: wc, wn, wg
      type(error_t), allocatable :: ec, en
      real(wp), allocatable :: qc(:), qn(:), dq(:), dv(:), da(:), from(:), lo(:), hi(:)
      real(wp) :: worst, r
      integer :: k, j, nd, nsteps
      integer(int64) :: seed
      logical :: used
      worst_v = 0.0_wp; worst_a = 0.0_wp; worst_lam = 0.0_wp; worst_fb = 0.0_wp
      worst_gap = 0.0_wp; worst_res = 0.0_wp
      small = 0
      wg%small_solves = .false.
      nd = size(deck%mech%drives)
      allocate (qc, source=linkage_reference_pose(deck%mech))
      allocate (qn, source=qc)
      allocate (dq(nd), dv(nd), da(nd), from(nd))
      from(:) = deck%mech%drives%q_ref
      allocate (lo, source=from)
      allocate (hi, source=from)
      worst = 0.0_wp
      used = .true.
      nsteps = deck%n
      seed = 12345
      do k = 1, nsteps + 40
        if (k <= nsteps) then
          call linkage_drive_values(deck, k, dq, dv, da)
          lo = min(lo, dq)
          hi = max(hi, dq)
        else
          ! a random drive value within the run's range (a linear congruential sequence)
          do j = 1, nd
            seed = modulo(seed * 48271_int64, 2147483647_int64)
            r = real(seed, wp) / 2147483647.0_wp
            dq(j) = lo(j) + r * (hi(j) - lo(j))
          end do
        end if
        call linkage_assemble(deck%mech, from, dq, qc, wc, ec)
        used = used .and. wc%closed
        call linkage_assemble_newton(deck%mech, from, dq, qn, wn, en, 1.0e-14_wp)
        if (allocated(ec) .or. allocated(en)) then
          call check_true(t, "linkage-closed-"//name, allocated(ec) .eqv. allocated(en), "step "//int_str(k)// &
            ": one solve fails, the other does not")
          if (.not. (allocated(ec) .and. allocated(en))) return
          ! (both fail: a drive value the linkage cannot reach; the steps before are compared)
          nsteps = min(nsteps, k - 1)
          exit
        end if
        worst = max(worst, maxval(abs(qc - qn)) / deck%mech%size)
        if (k <= nsteps) call solves_against_general(deck, qc, dv, da, wc, wg)
        from = dq
      end do
      call check_true(t, "linkage-closed-used-"//name, used, "a unit without a closed form")
      call check_true(t, "linkage-closed-newton-"//name, worst <= 1.0e-12_wp, "largest pose difference / size "// &
        real_str(worst)//" (limit 1e-12)")
      call check_true(t, "linkage-closed-solves-used-"//name, small == nsteps * size(deck%mech%units), &
        int_str(small)//" unit solves in closed form, expected every unit of every step: "// &
        int_str(nsteps * size(deck%mech%units)))
      call check_true(t, "linkage-closed-solves-"//name, max(worst_v, worst_a, worst_lam, worst_fb) <= 1.0e-12_wp, &
        "the fast path against the general J solve, largest difference relative to the step's largest: velocities "// &
        real_str(worst_v)//", accelerations "//real_str(worst_a)//", reactions "//real_str(worst_lam)// &
        ", group method's "//real_str(worst_fb)//" (limit 1e-12)")
      call check_true(t, "linkage-two-formulations-"//name, worst_gap <= 1.0e-9_wp .and. worst_res <= 1.0e-12_wp, &
        "over "//int_str(nsteps)//" steps: the group method against the Lagrange multipliers, largest gap / "// &
        "the step's largest reaction "//real_str(worst_gap)//" (limit 1e-9); largest equilibrium residual "// &
        real_str(worst_res)//" (limit 1e-12)")
    end subroutine compare
    !> One step's velocities, accelerations and reactions at poses q by the closed forms (wc)
    !> and by the general solve (wg: LU factors of every unit, the group method's systems
    !> by LU); the multipliers' reactions and the group method's each against their own
    !> general solve (the two formulations against each other: test_second_opinion), with
    !> loads of every kind (each force 100 N times its number, each moment 10 N*m times its
    !> number, gravity and inertia as the deck has them) and a drive acceleration of 3
    !> (rad/s^2 or m/s^2) on top of the deck's.
    subroutine solves_against_general(deck, q, dv, da, wc, wg)
      type(linkage_deck_t), intent(in) :: deck
      real(wp), intent(in) :: q(:), dv(:), da(:)
      type(linkage_work_t), intent(inout) :: wc, wg
      type(linkage_step_t) :: sc, sg, sf
      type(error_t), allocatable :: e1, e2
      real(wp) :: fval(size(deck%mech%forces)), mval(size(deck%mech%moment_link)), f2(2, size(deck%mech%pairs)), &
        n2(size(deck%mech%pairs)), c2(size(deck%mech%pairs)), e2v(size(deck%mech%drives))
      integer :: i
      do i = 1, size(fval)
        fval(i) = 100.0_wp * i
      end do
      do i = 1, size(mval)
        mval(i) = 10.0_wp * i
      end do
      sc%q = q
      sg%q = q
      allocate (sc%qd(size(q)), sc%qdd(size(q)), sg%qd(size(q)), sg%qdd(size(q)))
      call linkage_motion(deck%mech, q, dv, da + 3.0_wp, sc%qd, sc%qdd, wc, e1)
      call linkage_motion(deck%mech, q, dv, da + 3.0_wp, sg%qd, sg%qdd, wg, e2)
      if (allocated(e1) .or. allocated(e2)) then
        worst_v = huge(1.0_wp)
        return
      end if
      ! the units solved from the points (the fast path: every unit) or by J's closed forms
      if (wc%has_fast) then
        small = small + size(deck%mech%units)
      else
        small = small + count(wc%unit_small)
      end if
      worst_v = max(worst_v, maxval(abs(sc%qd - sg%qd)) / maxval(abs(sg%qd)))
      worst_a = max(worst_a, maxval(abs(sc%qdd - sg%qdd)) / maxval(abs(sg%qdd)))
      ! the reactions of the general solve's motion by both: the multipliers' solves alone
      sc%qd = sg%qd
      sc%qdd = sg%qdd
      call linkage_statics(deck%mech, fval, mval, sc, wc, e1)
      call linkage_statics(deck%mech, fval, mval, sg, wg, e2)
      if (allocated(e1) .or. allocated(e2)) then
        worst_lam = huge(1.0_wp)
        return
      end if
      worst_lam = max(worst_lam, linkage_reaction_gap(deck%mech, sg, sc%f, sc%normal, sc%couple, sc%effort))
      ! the two formulations against each other (linkage_statics' second opinion), both solves
      worst_gap = max(worst_gap, sc%solver_gap, sg%solver_gap)
      worst_res = max(worst_res, sc%residual, sg%residual)
      ! the group method's free bodies by the closed forms
      call linkage_free_body(deck%mech, fval, mval, sg, wc, f2, n2, c2, e2v, e1)
      if (allocated(e1)) then
        worst_fb = huge(1.0_wp)
        return
      end if
      ! against the group method by LU (as a step's reactions)
      sf%q = q
      allocate (sf%f(2, size(deck%mech%pairs)), sf%normal(size(deck%mech%pairs)), sf%couple(size(deck%mech%pairs)), &
                sf%effort(size(deck%mech%drives)))
      call linkage_free_body(deck%mech, fval, mval, sg, wg, sf%f, sf%normal, sf%couple, sf%effort, e2)
      if (allocated(e2)) then
        worst_fb = huge(1.0_wp)
        return
      end if
      worst_fb = max(worst_fb, linkage_reaction_gap(deck%mech, sf, f2, n2, c2, e2v))
      ! the closed forms' reactions (J by its rows' links, no second solve of their own)
      ! against the group method by LU: the two formulations, as the second opinion would
      worst_gap = max(worst_gap, linkage_reaction_gap(deck%mech, sc, sf%f, sf%normal, sf%couple, sf%effort))
    end subroutine solves_against_general
  end subroutine test_closed_forms

end module test_linkage
