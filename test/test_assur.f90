!> Tests of the generic Assur-group engine: LAPACK dyad solutions against independent Cramer
!> closed forms (2016 paper's method) for all five kinds; transfer functions against finite
!> differences; self-check of the three generic decks; an offset slider-crank solved by hand;
!> the T.FTN worked example (manual section 2); toggle positions; prescribed crank speed law.
module test_assur
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use kinetostat_kinds, only: wp, pi, deg_to_rad, rad_to_deg
  use kinetostat_text, only: int_str
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_vec2, only: perp, cross, unit_at, rotate, magnitude
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, dyad_geometry_t, &
    kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp, kind_names
  use kinetostat_assur_statics, only: dyad_reactions_t, dyad_reactions, pair_is_prismatic
  use kinetostat_assur, only: assur_mech_t, assur_link_t, assur_dyad_t, assur_step_t, assur_force_t, &
    assur_step, assur_kinematics, pair_index, crank_pin_index, pair_sides
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, assur_window, assur_phi1_deg, assur_omega1
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_assur_layout, only: assur_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_assur_tests

  !> State of the test's random generator (64-bit LCG, fixed seed: reproducible).
  integer, parameter :: i8 = selected_int_kind(18)

contains

  subroutine run_assur_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_cramer_oracle(t)
    call test_closed_form_vs_lu(t)
    call test_finite_differences(t)
    call test_deck_selfchecks(t)
    call test_slider_crank_by_hand(t)
    call test_sixbar_worked_example(t)
    call test_toggle(t)
    call test_parallel_groups(t)
    call test_many_groups(t)
    call test_prescribed_speed_law(t)
    call test_window(t)
    call test_rrr_angles(t)
    call test_link_angles_off(t)
  end subroutine run_assur_tests

  !> Uniform number in [lo, hi] from the LCG state.
  real(wp) function uniform(state, lo, hi)
    integer(i8), intent(inout) :: state
    real(wp), intent(in) :: lo, hi
    state = state * 6364136223846793005_i8 + 1442695040888963407_i8
    uniform = lo + (hi - lo) * (real(ishft(state, -11), wp) / 2.0_wp**53)
  end function uniform

  ! ----------------------------------------------------------------------------------------
  !> Cramer closed form of the reactions of one dyad (independent oracle). Known moments are
  !> about the inner pair's point p(:,2). Returns ok = false if the 2x2 determinant is small.
  subroutine cramer(kind, p, t, fk, mk, f, n, m, cond)
    integer, intent(in) :: kind
    real(wp), intent(in) :: p(2, 3), t(2, 3), fk(2, 2), mk(2)
    real(wp), intent(out) :: f(2, 3), n(3), m(3)
    !> |determinant| of the normalised 2x2 system (conditioning of the configuration).
    real(wp), intent(out) :: cond
    real(wp) :: ua(2), ub(2), la, lb, f1t, f3t, b(2), det, f1n, f3n, n1(2), n2(2), n3(2), ca(2), x, y
    f = 0.0_wp
    n = 0.0_wp
    m = 0.0_wp
    select case (kind)
    case (kind_rrr)
      ! tangential parts from each link's moments about B, the rest from the group's forces
      la = magnitude(p(:, 2) - p(:, 1)); ua = (p(:, 2) - p(:, 1)) / la
      lb = magnitude(p(:, 2) - p(:, 3)); ub = (p(:, 2) - p(:, 3)) / lb
      f1t = mk(1) / la
      f3t = mk(2) / lb
      b = -(fk(:, 1) + fk(:, 2) + f1t * perp(ua) + f3t * perp(ub))
      det = cross(ua, ub)
      f1n = cross(b, ub) / det
      f3n = cross(ua, b) / det
      f(:, 1) = f1n * ua + f1t * perp(ua)
      f(:, 3) = f3n * ub + f3t * perp(ub)
      f(:, 2) = -(f(:, 1) + fk(:, 1))
      cond = min(abs(det), la, lb)
    case (kind_rrp)
      la = magnitude(p(:, 2) - p(:, 1)); ua = (p(:, 2) - p(:, 1)) / la
      n3 = perp(t(:, 3))
      f1t = mk(1) / la
      b = -(fk(:, 1) + fk(:, 2) + f1t * perp(ua))
      det = cross(ua, n3)
      f1n = cross(b, n3) / det
      n(3) = cross(ua, b) / det
      f(:, 1) = f1n * ua + f1t * perp(ua)
      f(:, 3) = n(3) * n3
      m(3) = -mk(2)
      f(:, 2) = -(f(:, 1) + fk(:, 1))
      cond = min(abs(det), la)
    case (kind_rpr)
      ! block: M2 = -Ma; group moments about A and the lever's forces along t give F3
      n2 = perp(t(:, 2))
      m(2) = -mk(1)
      ca = p(:, 3) - p(:, 1)
      x = -dot_product(fk(:, 2), t(:, 2))
      det = cross(ca, n2)
      y = (-(mk(1) + mk(2)) - x * cross(ca, t(:, 2))) / det
      f(:, 3) = x * t(:, 2) + y * n2
      n(2) = dot_product(f(:, 3) + fk(:, 2), n2)
      f(:, 2) = n(2) * n2
      f(:, 1) = -(f(:, 2) + fk(:, 1))
      cond = abs(det)
    case (kind_prp)
      n1 = perp(t(:, 1)); n3 = perp(t(:, 3))
      b = -(fk(:, 1) + fk(:, 2))
      det = cross(n1, n3)
      n(1) = cross(b, n3) / det
      n(3) = cross(n1, b) / det
      f(:, 1) = n(1) * n1
      f(:, 3) = n(3) * n3
      m(1) = -mk(1)
      m(3) = -mk(2)
      f(:, 2) = -(f(:, 1) + fk(:, 1))
      cond = abs(det)
    case (kind_rpp)
      ! link b's forces give N2, N3 (Cramer); link a gives F1 and M2; link b's moments give M3
      n2 = perp(t(:, 2)); n3 = perp(t(:, 3))
      b = -fk(:, 2)
      det = cross(-n2, n3)
      n(2) = cross(b, n3) / det
      n(3) = cross(-n2, b) / det
      f(:, 2) = n(2) * n2
      f(:, 3) = n(3) * n3
      f(:, 1) = -(f(:, 2) + fk(:, 1))
      m(2) = -mk(1)
      m(3) = m(2) - mk(2) - cross(p(:, 3) - p(:, 1), f(:, 3))
      cond = abs(det)
    case default
      error stop "cramer: unknown dyad kind"
    end select
  end subroutine cramer

  !> Random well-conditioned configurations of every kind: dgesv vs Cramer to 1e-10.
  subroutine test_cramer_oracle(t)
    type(test_counts_t), intent(inout) :: t
    !> Relative tolerance on every component, scaled by the largest reaction.
    real(wp), parameter :: rtol = 1.0e-10_wp
    integer, parameter :: trials = 200
    integer(i8) :: state
    integer :: kind, trial, j, c, accepted, worst_trial
    real(wp) :: p(2, 3), tt(2, 3), fk(2, 2), mk(2), f(2, 3), n(3), m(3), cond, scale, err, worst
    type(dyad_reactions_t) :: r
    type(error_t), allocatable :: error
    character(len=64) :: name
    state = 20260521_i8
    do kind = 1, 5
      accepted = 0
      worst = 0.0_wp
      worst_trial = 0
      do trial = 1, 10 * trials
        if (accepted == trials) exit
        do j = 1, 3
          p(:, j) = [uniform(state, -1.0_wp, 1.0_wp), uniform(state, -1.0_wp, 1.0_wp)]
          tt(:, j) = unit_at(uniform(state, -pi, pi))
        end do
        ! coincident reference points where the kind has them
        select case (kind)
        case (kind_rrp)
          p(:, 3) = p(:, 2)
        case (kind_rpr)
          p(:, 2) = p(:, 1)
        case (kind_prp)
          p(:, 1) = p(:, 2); p(:, 3) = p(:, 2)
        case (kind_rpp)
          p(:, 2) = p(:, 1)
        case default
          continue  ! RRR: three distinct pins
        end select
        do j = 1, 2
          fk(:, j) = [uniform(state, -1.0e3_wp, 1.0e3_wp), uniform(state, -1.0e3_wp, 1.0e3_wp)]
          mk(j) = uniform(state, -300.0_wp, 300.0_wp)
        end do
        call cramer(kind, p, tt, fk, mk, f, n, m, cond)
        if (cond < 0.3_wp) cycle
        accepted = accepted + 1
        call dyad_reactions(kind, p, tt, p(:, 2), fk, mk, r, error)
        if (allocated(error)) then
          call check_true(t, "dyad "//kind_names(kind)//" LAPACK solve", .false., error%message)
          cycle
        end if
        scale = max(maxval(abs(f)), maxval(abs(m)), 1.0_wp)
        err = max(maxval(abs(r%f - f)), maxval(abs(r%n - n)), maxval(abs(r%m - m))) / scale
        if (err > worst) then
          worst = err
          worst_trial = accepted
        end if
        if (accepted <= 3) then
          do j = 1, 3
            do c = 1, 2
              write (name, '("dyad ",a," trial ",i0," pair ",i0," F(",i0,")")') kind_names(kind), accepted, j, c
              call check_close(t, trim(name), f(c, j), r%f(c, j), rtol, rtol * scale)
            end do
            write (name, '("dyad ",a," trial ",i0," pair ",i0," N, M")') kind_names(kind), accepted, j
            call check_close(t, trim(name), n(j), r%n(j), rtol, rtol * scale)
            call check_close(t, trim(name), m(j), r%m(j), rtol, rtol * scale)
          end do
        end if
      end do
      call check_true(t, "dyad "//kind_names(kind)//": enough well-conditioned trials", accepted == trials, &
                      "only some configurations accepted")
      write (name, '("worst ",es9.2," at trial ",i0)') worst, worst_trial
      call check_true(t, "dyad "//kind_names(kind)//": LAPACK = Cramer within 1e-10 on all trials", &
                      worst <= rtol, trim(name))
    end do
  end subroutine test_cramer_oracle

  ! ----------------------------------------------------------------------------------------
  !> The closed-form dyad solve against the six equations solved as one dense system (LU), on
  !> random configurations of every kind: the pairs' points as the poses place them
  !> (coinciding where the kind has them) and anywhere (the equations hold for any points),
  !> moments about a random point; the largest difference relative to the trial's largest
  !> reaction (forces in N, moments over the dyad's size) at most 1e-12, and the reactions
  !> satisfy both links' equilibrium to roundoff.
  subroutine test_closed_form_vs_lu(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-12_wp
    integer, parameter :: trials = 400
    integer(i8) :: state
    integer :: kind, trial, j, layout, n_closed
    real(wp) :: p(2, 3), tt(2, 3), fk(2, 2), mk(2), o(2), scale, size_d, err, worst, resid, worst_resid
    real(wp) :: fa(2), fb(2), ma, mb
    type(dyad_reactions_t) :: r, q
    type(error_t), allocatable :: error, error_lu
    character(len=96) :: name
    state = 20261128_i8
    do kind = 1, 5
      worst = 0.0_wp
      worst_resid = 0.0_wp
      n_closed = 0
      do layout = 1, 2
        do trial = 1, trials
          do j = 1, 3
            p(:, j) = [uniform(state, -1.0_wp, 1.0_wp), uniform(state, -1.0_wp, 1.0_wp)]
            tt(:, j) = unit_at(uniform(state, -pi, pi))
          end do
          if (layout == 1) then
            select case (kind)
            case (kind_rrp)
              p(:, 3) = p(:, 2)
            case (kind_rpr, kind_rpp)
              p(:, 2) = p(:, 1)
            case (kind_prp)
              p(:, 1) = p(:, 2); p(:, 3) = p(:, 2)
            case default
              continue
            end select
            o = p(:, 2)
          else
            o = [uniform(state, -1.0_wp, 1.0_wp), uniform(state, -1.0_wp, 1.0_wp)]
          end if
          do j = 1, 2
            fk(:, j) = [uniform(state, -1.0e4_wp, 1.0e4_wp), uniform(state, -1.0e4_wp, 1.0e4_wp)]
            mk(j) = uniform(state, -3.0e3_wp, 3.0e3_wp)
          end do
          call dyad_reactions(kind, p, tt, o, fk, mk, q, error_lu, dense=.true.)
          call dyad_reactions(kind, p, tt, o, fk, mk, r, error)
          if (allocated(error_lu) .neqv. allocated(error)) then
            call check_true(t, "closed form vs LU "//kind_names(kind)//": the same verdict", .false., &
                            "one of them failed")
            cycle
          end if
          if (allocated(error)) cycle
          n_closed = n_closed + 1
          size_d = max(maxval(abs(p(:, 1) - o)), maxval(abs(p(:, 2) - o)), maxval(abs(p(:, 3) - o)), 1.0e-3_wp)
          scale = max(maxval(abs(q%f)), maxval(abs(q%m)) / size_d)
          err = max(maxval(abs(r%f - q%f)), maxval(abs(r%n - q%n)), maxval(abs(r%m - q%m)) / size_d) / scale
          worst = max(worst, err)
          ! both links' equilibrium with the closed form's reactions (moments about o)
          fa = r%f(:, 1) + r%f(:, 2) + fk(:, 1)
          fb = -r%f(:, 2) + r%f(:, 3) + fk(:, 2)
          ma = cross(p(:, 1) - o, r%f(:, 1)) + r%m(1) + cross(p(:, 2) - o, r%f(:, 2)) + r%m(2) + mk(1)
          mb = -cross(p(:, 2) - o, r%f(:, 2)) - r%m(2) + cross(p(:, 3) - o, r%f(:, 3)) + r%m(3) + mk(2)
          resid = max(maxval(abs(fa)), maxval(abs(fb)), abs(ma) / size_d, abs(mb) / size_d) / scale
          worst_resid = max(worst_resid, resid)
        end do
      end do
      write (name, '("worst ",es9.2," of the largest reaction over ",i0," trials")') worst, n_closed
      call check_true(t, "closed form vs LU "//kind_names(kind)//": within 1e-12", worst <= rtol .and. &
                      n_closed > trials, trim(name))
      write (name, '("worst residual ",es9.2)') worst_resid
      call check_true(t, "closed form "//kind_names(kind)//": equilibrium of both links", worst_resid <= rtol, trim(name))
    end do
  end subroutine test_closed_form_vs_lu

  ! ----------------------------------------------------------------------------------------
  !> A crank at the origin plus the given dyads, links numbered 1.. in order, frame 0.
  function make_mech(dyads) result(mech)
    type(assur_dyad_t), intent(in) :: dyads(:)
    type(assur_mech_t) :: mech
    integer :: i
    allocate (mech%dyads, source=dyads)
    allocate (mech%links(0:2 * size(dyads) + 1))
    mech%links = [(assur_link_t(id=i), i=0, 2 * size(dyads) + 1)]
    allocate (mech%forces(0), mech%moment_link(0))
  end function make_mech

  function dyad(kind, on, at, ang_deg, l2, l3, e, mode, slot_at, slot_deg) result(dy)
    integer, intent(in) :: kind, on(2), mode
    real(wp), intent(in) :: at(2, 2), ang_deg(2), l2, l3, e, slot_at(2), slot_deg
    type(assur_dyad_t) :: dy
    dy%geom = dyad_geometry_t(kind=kind, mode=mode, l2=l2, l3=l3, e=e, slot_at=slot_at, &
                              slot_angle=slot_deg * deg_to_rad)
    dy%on = on
    dy%at = at
    dy%ang = ang_deg * deg_to_rad
  end function dyad

  !> The RRR pose's link angles (directions by algebra, no acos or sincos) against the
  !> trigonometric construction on 400 random four-bars, both modes, each at 36 crank
  !> angles with A->C along every direction (the negative x-axis included): th_a =
  !> atan2(A->C) + mode * acos(law of cosines) on that branch (not reduced), th_b = the
  !> direction C->B, within 1e-12 rad (a jump of 2 pi would be 6.3 rad); the direction
  !> cosines equal cos and sin of the angles within 1e-14.
  subroutine test_rrr_angles(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t) :: mech
    type(link_state_t) :: states(0:3)
    type(dyad_pose_t) :: poses(1)
    type(error_t), allocatable :: error
    real(wp), parameter :: z2(2) = 0.0_wp
    integer(i8) :: state
    real(wp) :: r1, l2, l3, d_pivot(2), phi, a(2), d(2), l, tha_ref, thb_ref, worst_a, worst_b, worst_e, b(2)
    integer :: trial, k, mode, tried
    state = 20261129_i8
    worst_a = 0.0_wp
    worst_b = 0.0_wp
    worst_e = 0.0_wp
    tried = 0
    do trial = 1, 400
      mode = merge(1, -1, mod(trial, 2) == 0)
      r1 = uniform(state, 0.05_wp, 0.3_wp)
      ! C on the frame anywhere around A; links long enough to assemble at every angle
      phi = uniform(state, -pi, pi)
      d_pivot = uniform(state, 0.5_wp, 2.0_wp) * [cos(phi), sin(phi)]
      if (mod(trial, 5) == 0) d_pivot(2) = 0.0_wp  ! A->C along the x-axis at phi = 0, 180
      l2 = uniform(state, 0.5_wp, 2.5_wp)
      l3 = uniform(state, 0.5_wp, 2.5_wp)
      mech = make_mech([dyad(kind_rrr, [1, 0], reshape([r1, 0.0_wp, d_pivot(1), d_pivot(2)], [2, 2]), &
                             [0.0_wp, 0.0_wp], l2, l3, 0.0_wp, mode, z2, 0.0_wp)])
      do k = 0, 35
        phi = real(k, wp) * 10.0_wp * deg_to_rad
        a = r1 * [cos(phi), sin(phi)]
        d = d_pivot - a
        l = magnitude(d)
        if (abs((l2**2 + l**2 - l3**2) / (2.0_wp * l2 * l)) > 0.999_wp) cycle
        call assur_kinematics(mech, phi, states, poses, error)
        if (allocated(error)) then
          call check_true(t, "RRR angles: assembles", .false., error%message)
          return
        end if
        tried = tried + 1
        tha_ref = atan2(d(2), d(1)) + real(mode, wp) * acos((l2**2 + l**2 - l3**2) / (2.0_wp * l2 * l))
        b = a + l2 * [cos(tha_ref), sin(tha_ref)]
        thb_ref = atan2(b(2) - d_pivot(2), b(1) - d_pivot(1))
        worst_a = max(worst_a, abs(states(2)%th - tha_ref))
        worst_b = max(worst_b, abs(states(3)%th - thb_ref))
        worst_e = max(worst_e, abs(states(2)%cos_th - cos(states(2)%th)), abs(states(2)%sin_th - sin(states(2)%th)), &
                      abs(states(3)%cos_th - cos(states(3)%th)), abs(states(3)%sin_th - sin(states(3)%th)))
      end do
    end do
    call check_true(t, "RRR angles: positions tried", tried > 5000, "only "//int_str(tried))
    call check_close(t, "RRR angles: th_a against atan2 + mode*acos, rad", 0.0_wp, worst_a, 0.0_wp, 1.0e-12_wp)
    call check_close(t, "RRR angles: th_b against atan2(C->B), rad", 0.0_wp, worst_b, 0.0_wp, 1.0e-12_wp)
    call check_close(t, "RRR angles: directions against cos, sin of th", 0.0_wp, worst_e, 0.0_wp, 1.0e-14_wp)
  end subroutine test_rrr_angles

  !> Angle difference wrapped to (-pi, pi].
  pure real(wp) function wrap(x)
    real(wp), intent(in) :: x
    wrap = x - 2.0_wp * pi * anint(x / (2.0_wp * pi))
  end function wrap

  !> Three two-dyad mechanisms of all five kinds with moving guides (massless, unloaded):
  !> RRR+RRP (the RRP's guide on the RRR's link a), RPR+PRP, RPR+RPP.
  function two_dyad_mechs() result(mechs)
    type(assur_mech_t) :: mechs(3)
    real(wp), parameter :: z2(2) = 0.0_wp
    mechs(1) = make_mech([ &
      dyad(kind_rrr, [1, 0], reshape([0.1_wp, 0.0_wp, 0.35_wp, 0.05_wp], [2, 2]), [0.0_wp, 0.0_wp], &
           0.3_wp, 0.25_wp, 0.0_wp, 1, z2, 0.0_wp), &
      dyad(kind_rrp, [3, 2], reshape([0.15_wp, 0.05_wp, 0.0_wp, 0.02_wp], [2, 2]), [0.0_wp, 5.0_wp], &
           0.2_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)])
    mechs(2) = make_mech([ &
      dyad(kind_rpr, [1, 0], reshape([0.1_wp, 0.0_wp, 0.3_wp, 0.0_wp], [2, 2]), [0.0_wp, 0.0_wp], &
           0.0_wp, 0.0_wp, 0.03_wp, 1, z2, 0.0_wp), &
      dyad(kind_prp, [3, 0], reshape([0.2_wp, 0.0_wp, 0.0_wp, 0.25_wp], [2, 2]), [90.0_wp, 0.0_wp], &
           0.0_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)])
    mechs(3) = make_mech([ &
      dyad(kind_rpr, [1, 0], reshape([0.1_wp, 0.0_wp, 0.3_wp, 0.0_wp], [2, 2]), [0.0_wp, 0.0_wp], &
           0.0_wp, 0.0_wp, 0.0_wp, -1, z2, 0.0_wp), &
      dyad(kind_rpp, [0, 3], reshape([0.5_wp, 0.1_wp, 0.1_wp, 0.05_wp], [2, 2]), [0.0_wp, 20.0_wp], &
           0.0_wp, 0.0_wp, 0.0_wp, 1, [0.05_wp, 0.02_wp], 70.0_wp)])
  end function two_dyad_mechs

  !> Transfer functions of every link of three test mechanisms (all five kinds, moving guides)
  !> against central differences of the positions.
  subroutine test_finite_differences(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t) :: mechs(3)
    character(len=*), parameter :: labels(3) = ["RRR+RRP", "RPR+PRP", "RPR+RPP"]
    mechs = two_dyad_mechs()
    call fd_mech(t, mechs(1), labels(1))
    call fd_mech(t, mechs(2), labels(2))
    call fd_mech(t, mechs(3), labels(3))
  end subroutine test_finite_differences

  subroutine fd_mech(t, mech, label)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t), intent(in) :: mech
    character(*), intent(in) :: label
    !> FD step, rad; tolerances relative 1e-6, absolute 1e-6 (m/rad or rad/rad).
    real(wp), parameter :: h = 1.0e-4_wp, rtol = 1.0e-6_wp, atol = 1.0e-6_wp
    type(link_state_t) :: s0(0:5), sm(0:5), sp(0:5)
    type(dyad_pose_t) :: poses(2), pm(2), pp(2)
    type(error_t), allocatable :: e0, em, ep
    real(wp) :: phi
    integer :: k, i, c, assembled, d, j, sides(2)
    character(len=80) :: at
    assembled = 0
    do k = 0, 23
      phi = (7.0_wp + 15.0_wp * k) * deg_to_rad
      call assur_kinematics(mech, phi, s0, poses, e0)
      call assur_kinematics(mech, phi - h, sm, pm, em)
      call assur_kinematics(mech, phi + h, sp, pp, ep)
      if (allocated(e0) .or. allocated(em) .or. allocated(ep)) cycle
      assembled = assembled + 1
      do i = 2, 5
        write (at, '(a," link ",i0," at phi1=",f6.1)') label, i, phi * rad_to_deg
        call check_close(t, "u "//trim(at), wrap(sp(i)%th - sm(i)%th) / (2 * h), s0(i)%u, rtol, atol)
        call check_close(t, "eps_q "//trim(at), (wrap(sp(i)%th - s0(i)%th) - wrap(s0(i)%th - sm(i)%th)) / h**2, &
                         s0(i)%eq, rtol, atol)
        do c = 1, 2
          call check_close(t, "v_q origin "//trim(at), (sp(i)%o(c) - sm(i)%o(c)) / (2 * h), s0(i)%vo(c), rtol, atol)
          call check_close(t, "a_q origin "//trim(at), (sp(i)%o(c) - 2 * s0(i)%o(c) + sm(i)%o(c)) / h**2, &
                           s0(i)%ao(c), rtol, atol)
        end do
      end do
      ! strokes of the prismatic pairs (actuator length, speed and acceleration analogues)
      do d = 1, 2
        do j = 1, 3
          if (.not. pair_is_prismatic(mech%dyads(d)%geom%kind, j)) cycle
          write (at, '(a," dyad ",i0," pair ",i0," at phi1=",f6.1)') label, d, j, phi * rad_to_deg
          call check_close(t, "stroke' "//trim(at), (pp(d)%stroke(j) - pm(d)%stroke(j)) / (2 * h), &
                           poses(d)%stroke_v(j), rtol, atol)
          call check_close(t, "stroke'' "//trim(at), (pp(d)%stroke(j) - 2 * poses(d)%stroke(j) + pm(d)%stroke(j)) &
                           / h**2, poses(d)%stroke_a(j), rtol, atol)
          ! the sliding side's point at the pair moves along `extend` at stroke' relative to the other side
          sides = pair_sides(mech, d, j)
          call check_close(t, "stroke' = relative sliding speed "//trim(at), &
                           dot_product(point_velocity(s0(sides(1)), poses(d)%p(:, j)) &
                                       - point_velocity(s0(sides(2)), poses(d)%p(:, j)), poses(d)%extend(:, j)), &
                           poses(d)%stroke_v(j), 1.0e-12_wp, 1.0e-12_wp)
        end do
      end do
    end do
    call check_true(t, label//": assembled at >= 8 of 24 test angles", assembled >= 8, "too few")
  end subroutine fd_mech

  !> Velocity analogue (m/rad) of the point of link `ls` now at `p` (m).
  pure function point_velocity(ls, p) result(v)
    type(link_state_t), intent(in) :: ls
    real(wp), intent(in) :: p(2)
    real(wp) :: v(2)
    v = ls%vo + ls%u * perp(p - ls%o)
  end function point_velocity

  ! ----------------------------------------------------------------------------------------
  !> Every step of the three generic decks: equilibrium residual and power balance <= 1e-9.
  subroutine test_deck_selfchecks(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: decks(3) = [character(len=32) :: "data/assur_sixbar.nml", &
      "data/assur_pr3207.nml", "data/assur_slider_crank.nml"]
    real(wp), parameter :: limit = 1.0e-9_wp
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    character(len=80) :: detail
    integer :: i, k
    do i = 1, size(decks)
      if (.not. read_test_deck(t, trim(decks(i)), deck)) cycle
      call assur_solve(trim(decks(i)), deck, steps, error)
      call check_true(t, "solve "//trim(decks(i)), .not. allocated(error), "geometry error")
      if (allocated(error)) cycle
      call check_true(t, trim(decks(i))//" has 13 steps", size(steps) == 13, "wrong step count")
      do k = 1, size(steps)
        write (detail, '(a," step ",i0,": residual ",es10.3,", mismatch ",es10.3)') trim(decks(i)), k, &
          steps(k)%residual, steps(k)%mismatch
        call check_true(t, "assur equilibrium residual <= 1e-9", steps(k)%residual <= limit, trim(detail))
        call check_true(t, "assur M1 power balance <= 1e-9", steps(k)%mismatch <= limit, trim(detail))
      end do
    end do
  end subroutine test_deck_selfchecks

  !> Whether the bundled deck `path` is read into `deck` (a failed check with the reader's
  !> message otherwise).
  logical function read_test_deck(t, path, deck) result(ok)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path
    type(assur_deck_t), intent(out) :: deck
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    call load_deck(path, source, error)
    if (.not. allocated(error)) call read_assur_deck(source, deck, error)
    ok = .not. allocated(error)
    if (ok) then
      call check_true(t, "read "//path, .true., "")
    else
      call check_true(t, "read "//path, .false., error%message)
    end if
  end function read_test_deck

  ! ----------------------------------------------------------------------------------------
  !> data/assur_slider_crank.nml against a hand solution: slider-crank with an offset guide
  !> y = e, rod with an off-axis centre of mass, omega1 const (crank centre of mass at O).
  !> Kinematics in closed form (sin th = (e - r sin phi)/l), slider's x-equation, the rod's
  !> moments about A, then the slider's y-equation, the rod's and the crank's forces.
  subroutine test_slider_crank_by_hand(t)
    type(test_counts_t), intent(inout) :: t
    !> The deck's data, typed again here.
    real(wp), parameter :: r = 0.1_wp, l = 0.35_wp, e = 0.02_wp, w = 50.0_wp, g = 9.81_wp
    real(wp), parameter :: m1 = 2.0_wp, m2 = 1.5_wp, j2 = 0.02_wp, s2(2) = [0.12_wp, 0.01_wp], m3 = 3.0_wp
    real(wp), parameter :: rtol = 1.0e-9_wp
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    real(wp) :: phi, sth, cth, th, u, eq, xbqq, a(2), b(2), ws(2), a_s2(2), g2(2), phi2(2), mphi2
    real(wp) :: f32(2), f21(2), f12(2), f10(2), mm1, nn, p_val, scale
    integer :: k
    character(len=40) :: at
    if (.not. read_test_deck(t, "data/assur_slider_crank.nml", deck)) return
    call assur_solve("slider", deck, steps, error)
    if (allocated(error)) then
      call check_true(t, "solve slider-crank deck", .false., error%message)
      return
    end if
    do k = 1, size(steps)
      phi = assur_phi1_deg(deck, k) * deg_to_rad
      p_val = merge(500.0_wp, 100.0_wp, assur_phi1_deg(deck, k) <= 180.0_wp)
      sth = (e - r * sin(phi)) / l
      cth = sqrt(1.0_wp - sth**2)
      th = atan2(sth, cth)
      u = -r * cos(phi) / (l * cth)
      eq = (r * sin(phi) + l * sth * u**2) / (l * cth)
      xbqq = -r * cos(phi) - l * cth * u**2 - l * sth * eq
      a = r * [cos(phi), sin(phi)]
      b = a + l * [cth, sth]
      ws = rotate(s2, th)
      a_s2 = w**2 * (-a + eq * perp(ws) - u**2 * ws)
      g2 = [0.0_wp, -m2 * g]
      phi2 = -m2 * a_s2
      mphi2 = -j2 * eq * w**2
      f32(1) = p_val + m3 * xbqq * w**2
      f32(2) = ((b(2) - a(2)) * f32(1) + cross(ws, g2 + phi2) + mphi2) / (b(1) - a(1))
      nn = -f32(2) + m3 * g
      f21 = f32 - g2 - phi2
      f12 = -f21
      f10 = -(f12 + [0.0_wp, -m1 * g])
      mm1 = -cross(a, f12)
      scale = max(magnitude(f21), magnitude(f10), 1.0_wp)
      write (at, '(" at phi1=",f6.1)') assur_phi1_deg(deck, k)
      associate (s => steps(k))
        call check_close(t, "slider-crank F21x"//trim(at), f21(1), s%f(1, pair_index(1, 1)), rtol, rtol * scale)
        call check_close(t, "slider-crank F21y"//trim(at), f21(2), s%f(2, pair_index(1, 1)), rtol, rtol * scale)
        call check_close(t, "slider-crank F23x"//trim(at), -f32(1), s%f(1, pair_index(1, 2)), rtol, rtol * scale)
        call check_close(t, "slider-crank F23y"//trim(at), -f32(2), s%f(2, pair_index(1, 2)), rtol, rtol * scale)
        call check_close(t, "slider-crank F30 N"//trim(at), nn, s%n(pair_index(1, 3)), rtol, rtol * scale)
        call check_close(t, "slider-crank F30 M"//trim(at), 0.0_wp, s%m(pair_index(1, 3)), rtol, rtol * scale * r)
        call check_close(t, "slider-crank F10x"//trim(at), f10(1), s%f(1, crank_pin_index(1)), rtol, rtol * scale)
        call check_close(t, "slider-crank F10y"//trim(at), f10(2), s%f(2, crank_pin_index(1)), rtol, rtol * scale)
        call check_close(t, "slider-crank M1"//trim(at), mm1, s%m1, rtol, rtol * scale * r)
      end associate
    end do
  end subroutine test_slider_crank_by_hand

  ! ----------------------------------------------------------------------------------------
  !> The manual's worked example (section 2, 30 deg after the extreme position, g = 10) on
  !> data/assur_sixbar.nml. Tolerances follow the printed digits. eps_q2 is the corrected
  !> value (sixbar.md erratum), not the printed 0.201638.
  subroutine test_sixbar_worked_example(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_deck_t) :: deck
    type(assur_step_t) :: s
    type(error_t), allocatable :: error
    type(link_state_t) :: st(0:5)
    type(dyad_pose_t) :: poses(2)
    real(wp) :: phi1, rot2, x2(2), f45(2), f43(2), phi4, m54e, l_eh, a_s4(2), a_h, m54e_formula
    if (.not. read_test_deck(t, "data/assur_sixbar.nml", deck)) return
    deck%mech%g = 10.0_wp
    ! the manual's printed values belong to phi1 = 66.8 deg exactly (the rounded angle; at
    ! 36.7706 + 30 = 66.7706 u31 is 0.22664, not 0.22677); its figures carry ~4 digits
    phi1 = 66.8_wp * deg_to_rad
    rot2 = deck%pair_frame(4)
    x2 = unit_at(rot2)
    call assur_kinematics(deck%mech, phi1, st, poses, error)
    if (allocated(error)) then
      call check_true(t, "sixbar kinematics", .false., error%message)
      return
    end if
    call check_close(t, "sixbar extreme position + 30 = 66.8", 66.8_wp, deck%phi_start + 30.0_wp, 0.0_wp, 0.03_wp)
    call check_close(t, "sixbar phi2 = 31.34", 31.34_wp, st(2)%th * rad_to_deg, 0.0_wp, 0.01_wp)
    call check_close(t, "sixbar phi3 = 89.83 (exact)", 89.83_wp, st(3)%th * rad_to_deg, 0.0_wp, 0.01_wp)
    phi4 = modulo((st(4)%th - rot2) * rad_to_deg, 360.0_wp)
    call check_close(t, "sixbar phi4 = 354.84 (frame 2)", 354.84_wp, phi4, 0.0_wp, 0.02_wp)
    call check_close(t, "sixbar u21", -0.11478_wp, st(2)%u, 0.0_wp, 2.0e-4_wp)
    call check_close(t, "sixbar u31", 0.22677_wp, st(3)%u, 0.0_wp, 2.0e-4_wp)
    call check_close(t, "sixbar u41", -0.15355_wp, st(4)%u, 0.0_wp, 2.0e-4_wp)
    call check_close(t, "sixbar eps_q2 = 0.2326 (erratum: manual prints 0.201638)", 0.2326_wp, st(2)%eq, &
                     0.0_wp, 1.0e-4_wp)
    call check_close(t, "sixbar eps_q3", 0.30750_wp, st(3)%eq, 0.0_wp, 2.0e-4_wp)
    call check_close(t, "sixbar eps_q4", -0.14116_wp, st(4)%eq, 0.0_wp, 2.0e-4_wp)
    call check_close(t, "sixbar a_qH (along x2)", -0.09657_wp, dot_product(st(5)%ao, x2), 0.0_wp, 2.0e-4_wp)
    call assur_step(deck%mech, phi1, assur_omega1(deck, 1), 0.0_wp, [1000.0_wp], [real(wp) ::], s, error)
    if (allocated(error)) then
      call check_true(t, "sixbar step", .false., error%message)
      return
    end if
    ! group 4-5 in frame 2. The manual's figures (F56 = -615.4, F54 = (-6854, 615.4),
    ! F43 = (-8733, 891.4), M54E = 122.58) were computed from its rounded kinematics
    ! (phi4 = 354.84 where the exact value is 354.855; M54E ~ sin(phi4) is small, so that
    ! 0.015 deg moves it by 0.4%): checked to 0.5%. The manual's formula (9) itself is then
    ! checked exactly: M54E from the engine's kinematics and loads, F56 = -M54E/(l_EH cos phi4).
    call check_close(t, "sixbar F56 (y2) = -615.4", -615.4_wp, s%n(pair_index(2, 3)), 5.0e-3_wp, 0.0_wp)
    f45 = rotate(s%f(:, pair_index(2, 2)), -rot2)
    call check_close(t, "sixbar F54x = -6854", -6854.0_wp, -f45(1), 5.0e-3_wp, 0.0_wp)
    call check_close(t, "sixbar F54y = 615.4", 615.4_wp, -f45(2), 5.0e-3_wp, 0.0_wp)
    f43 = rotate(s%f(:, pair_index(2, 1)), -rot2)
    call check_close(t, "sixbar F43x = -8733", -8733.0_wp, f43(1), 5.0e-3_wp, 0.0_wp)
    call check_close(t, "sixbar F43y = 891.4", 891.4_wp, f43(2), 5.0e-3_wp, 0.0_wp)
    l_eh = 0.2_wp
    m54e = -s%n(pair_index(2, 3)) * l_eh * cos(phi4 * deg_to_rad)
    call check_close(t, "sixbar M54E = 122.58", 122.58_wp, m54e, 5.0e-3_wp, 0.0_wp)
    ! formula (9) with exact kinematics: loads along x2 (F5 + G5 + Phi5) at H, Phi4 + G4 at S4
    a_s4 = rotate(st(4)%ao, -rot2) + st(4)%eq * perp(0.1_wp * unit_at(st(4)%th - rot2)) &
           - st(4)%u**2 * 0.1_wp * unit_at(st(4)%th - rot2)
    a_s4 = a_s4 * assur_omega1(deck, 1)**2
    a_h = dot_product(st(5)%ao, x2) * assur_omega1(deck, 1)**2
    m54e_formula = -(1000.0_wp + 6.0_wp * 10.0_wp - 6.0_wp * a_h) * l_eh * sin(phi4 * deg_to_rad) &
                   - (-2.0_wp * a_s4(1) + 2.0_wp * 10.0_wp) * 0.1_wp * sin(phi4 * deg_to_rad) &
                   + (-2.0_wp * a_s4(2)) * 0.1_wp * cos(phi4 * deg_to_rad) - 0.007_wp * st(4)%eq * assur_omega1(deck, 1)**2
    call check_close(t, "sixbar F56 = -M54E/(l_EH cos phi4), manual formula (9), exact", &
                     -m54e_formula / (l_eh * cos(phi4 * deg_to_rad)), s%n(pair_index(2, 3)), 1.0e-9_wp, 1.0e-9_wp)
    call check_true(t, "sixbar worked example self-check", s%residual <= 1.0e-9_wp .and. s%mismatch <= 1.0e-9_wp, &
                    "residual or power mismatch above 1e-9")
  end subroutine test_sixbar_worked_example

  ! ----------------------------------------------------------------------------------------
  !> Dead-centre (toggle) positions are geometry errors, never NaN: an RRR dyad stretched
  !> exactly folded (A = (1,0), C = (2,0), l2 - l3 = 1: B = (3,0)) and a singular statics system.
  subroutine test_toggle(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t) :: mech
    type(assur_step_t) :: s
    type(error_t), allocatable :: error
    type(dyad_reactions_t) :: r
    real(wp), parameter :: z2(2) = 0.0_wp
    real(wp) :: p(2, 3), tz(2, 3)
    mech = make_mech([dyad(kind_rrr, [1, 0], reshape([1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp], [2, 2]), &
                           [0.0_wp, 0.0_wp], 2.0_wp, 1.0_wp, 0.0_wp, 1, z2, 0.0_wp)])
    mech%g = 9.81_wp
    mech%links(2)%m = 1.0_wp
    call assur_step(mech, 0.0_wp, 10.0_wp, 0.0_wp, [real(wp) ::], [real(wp) ::], s, error)
    call check_true(t, "toggle RRR: geometry error", allocated(error), "no error at the dead centre")
    if (allocated(error)) then
      call check_true(t, "toggle RRR: exit code 3", error%code == exit_geometry, error%message)
      call check_true(t, "toggle RRR: message says dead position", index(error%message, "dead") > 0, error%message)
    end if
    ! just off the toggle it assembles and is finite
    call assur_step(mech, 5.0_wp * deg_to_rad, 10.0_wp, 0.0_wp, [real(wp) ::], [real(wp) ::], s, error)
    call check_true(t, "near toggle RRR: solvable", .not. allocated(error), "unexpected error")
    ! collinear A, B, C: the six equations are singular
    p = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 3.0_wp, 0.0_wp], [2, 3])
    tz = 0.0_wp
    call dyad_reactions(kind_rrr, p, tz, p(:, 2), &
                        reshape([0.0_wp, -10.0_wp, 0.0_wp, -5.0_wp], [2, 2]), [1.0_wp, 2.0_wp], r, error)
    call check_true(t, "collinear RRR statics: geometry error", allocated(error), "LAPACK solved a singular system")
    if (allocated(error)) call check_true(t, "collinear RRR statics: exit code 3", error%code == exit_geometry, &
                                          error%message)
    ! PRP with parallel guides cannot be assembled
    mech = make_mech([dyad(kind_prp, [1, 0], reshape([0.1_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 2]), &
                           [0.0_wp, 0.0_wp], 0.0_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)])
    call assur_step(mech, 0.0_wp, 1.0_wp, 0.0_wp, [real(wp) ::], [real(wp) ::], s, error)
    call check_true(t, "parallel PRP guides: geometry error", allocated(error), "no error")
  end subroutine test_toggle

  ! ----------------------------------------------------------------------------------------
  !> Two groups hanging on the crank in parallel (a V-twin: two RRP groups on the same crank
  !> pin, guides at 0 and 90 deg): each group's reactions are those it has alone, and the
  !> massless crank's pin reaction and balancing moment are the sums (2016 paper's note).
  subroutine test_parallel_groups(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: z2(2) = 0.0_wp, rtol = 1.0e-12_wp
    type(assur_dyad_t) :: d1, d2
    type(assur_mech_t) :: both, one, two
    type(assur_step_t) :: sb, s1, s2
    type(error_t), allocatable :: e0, e1, e2
    real(wp) :: phi, scale
    integer :: k, c, j
    character(len=40) :: at
    d1 = dyad(kind_rrp, [1, 0], reshape([0.1_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 2]), [0.0_wp, 0.0_wp], &
              0.4_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)
    d2 = dyad(kind_rrp, [1, 0], reshape([0.1_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 2]), [0.0_wp, 90.0_wp], &
              0.4_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)
    both = make_mech([d1, d2])
    one = make_mech([d1])
    two = make_mech([d2])
    both%links(2:5) = [assur_link_t(id=2, m=1.2_wp, j=0.02_wp, s=[0.15_wp, 0.01_wp]), assur_link_t(id=3, m=2.0_wp), &
                       assur_link_t(id=4, m=1.1_wp, j=0.03_wp, s=[0.2_wp, 0.0_wp]), assur_link_t(id=5, m=2.5_wp)]
    one%links(2:3) = both%links(2:3)
    two%links(2:3) = both%links(4:5)
    both%g = 9.81_wp; one%g = 9.81_wp; two%g = 9.81_wp
    do k = 0, 11
      phi = (10.0_wp + 30.0_wp * k) * deg_to_rad
      write (at, '(" at phi1=",f6.1)') phi * rad_to_deg
      call assur_step(both, phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], sb, e0)
      call assur_step(one, phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], s1, e1)
      call assur_step(two, phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], s2, e2)
      if (allocated(e0) .or. allocated(e1) .or. allocated(e2)) then
        call check_true(t, "parallel groups solvable"//trim(at), .false., "geometry error")
        cycle
      end if
      scale = max(magnitude(sb%f(:, 7)), 1.0_wp)
      do c = 1, 2
        call check_close(t, "parallel: crank pin = sum"//trim(at), s1%f(c, 4) + s2%f(c, 4), sb%f(c, 7), rtol, rtol * scale)
        do j = 1, 3
          call check_close(t, "parallel: group 1 as alone"//trim(at), s1%f(c, j), sb%f(c, j), rtol, rtol * scale)
          call check_close(t, "parallel: group 2 as alone"//trim(at), s2%f(c, j), sb%f(c, 3 + j), rtol, rtol * scale)
        end do
      end do
      call check_close(t, "parallel: M1 = sum"//trim(at), s1%m1 + s2%m1, sb%m1, rtol, rtol * scale * 0.1_wp)
      call check_true(t, "parallel: self-check"//trim(at), sb%residual <= 1.0e-12_wp .and. sb%mismatch <= 1.0e-12_wp, &
                      "residual or power mismatch above 1e-12")
    end do
  end subroutine test_parallel_groups

  ! ----------------------------------------------------------------------------------------
  !> A mechanism of more dyads than assur_step keeps in fixed arrays (4): six sliders on the
  !> crank, each on a guide of its own. Its first four groups' reactions are the same bits as
  !> in the mechanism of those four alone (the later groups hang on the crank and the frame
  !> only, and dyads are solved last to first), and one result reused over the steps (its
  !> workspace kept, as the layout's threads do) gives the same bits as a fresh one per step,
  !> also when it goes from 5 to 6 dyads and back.
  subroutine test_many_groups(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: z2(2) = 0.0_wp
    real(wp), parameter :: guides(6) = [0.0_wp, 90.0_wp, 45.0_wp, 135.0_wp, 30.0_wp, 150.0_wp]
    type(assur_dyad_t) :: groups(6)
    type(assur_mech_t) :: four, many(5:6)
    type(assur_step_t) :: s4, reused, fresh
    type(error_t), allocatable :: e4, er, ef
    real(wp) :: phi
    integer :: k, g, nd, bad_four, bad_reuse
    do g = 1, 6
      groups(g) = dyad(kind_rrp, [1, 0], reshape([0.1_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 2]), [0.0_wp, guides(g)], &
                       0.4_wp, 0.0_wp, 0.0_wp, 1, z2, 0.0_wp)
    end do
    four = make_mech(groups(1:4))
    do nd = 5, 6
      many(nd) = make_mech(groups(1:nd))
      do g = 2, 2 * nd + 1
        many(nd)%links(g) = assur_link_t(id=g, m=1.0_wp + 0.1_wp * g, j=0.01_wp * g, s=[0.05_wp * mod(g, 3), 0.01_wp])
      end do
      many(nd)%g = 9.81_wp
    end do
    four%links(2:9) = many(5)%links(2:9)
    four%g = 9.81_wp
    bad_four = 0
    bad_reuse = 0
    do k = 0, 23
      phi = (10.0_wp + 15.0_wp * k) * deg_to_rad
      nd = 5 + mod(k / 4, 2)
      call assur_step(four, phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], s4, e4)
      call assur_step(many(nd), phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], reused, er)
      fresh = assur_step_t()
      call assur_step(many(nd), phi, 30.0_wp, 5.0_wp, [real(wp) ::], [real(wp) ::], fresh, ef)
      if (allocated(e4) .or. allocated(er) .or. allocated(ef)) then
        call check_true(t, "many groups solvable at step "//int_str(k), .false., "geometry error")
        cycle
      end if
      ! pairs 1..12 are the four groups' (3 each)
      if (any(transfer(s4%f(:, 1:12), 0_i8, 24) /= transfer(reused%f(:, 1:12), 0_i8, 24))) bad_four = bad_four + 1
      if (any(transfer(reused%f, 0_i8, size(reused%f)) /= transfer(fresh%f, 0_i8, size(fresh%f))) .or. &
          reused%m1 /= fresh%m1 .or. reused%m1_power /= fresh%m1_power .or. &
          reused%residual /= fresh%residual .or. reused%mismatch /= fresh%mismatch) bad_reuse = bad_reuse + 1
    end do
    call check_true(t, "more than 4 dyads: the first four groups as in the 4-dyad mechanism (bits, 24 steps)", &
                    bad_four == 0, int_str(bad_four)//" steps differ")
    call check_true(t, "more than 4 dyads: a reused result as a fresh one (bits, 24 steps, 5 and 6 dyads)", &
                    bad_reuse == 0, int_str(bad_reuse)//" steps differ")
    call check_true(t, "more than 4 dyads: the self-check of the last step", &
                    reused%residual <= 1.0e-12_wp .and. reused%mismatch <= 1.0e-12_wp, "residual or mismatch above 1e-12")
  end subroutine test_many_groups

  ! ----------------------------------------------------------------------------------------
  !> A step solved without the links' angles (assur_step_t%link_angles = .false., as a run
  !> that shows none solves it) gives the same bits as one with them: every pair force,
  !> normal force and couple, M1 and its power value, the self-check's residual and
  !> mismatch, every link's frame but its angle; the angles of a dyad a later dyad turns its
  !> guide with (RRR+RRP: the RRP's guide on the RRR's link a), of an RPR, PRP or RPP and of
  !> a guided slider are still the same, those of an RRR (the four-bar) and of an RRP's link
  !> a are NaN. Four mechanisms of all five kinds with masses, 24 crank angles.
  subroutine test_link_angles_off(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t) :: mechs(4)
    real(wp), parameter :: z2(2) = 0.0_wp
    type(assur_step_t) :: with, without
    type(error_t), allocatable :: e1, e2
    real(wp) :: phi
    integer :: m, k, g, bad, solved, nan_bad
    mechs(1:3) = two_dyad_mechs()
    mechs(4) = make_mech([dyad(kind_rrr, [1, 0], reshape([0.1_wp, 0.0_wp, 0.3_wp, 0.0_wp], [2, 2]), &
                               [0.0_wp, 0.0_wp], 0.35_wp, 0.25_wp, 0.0_wp, 1, z2, 0.0_wp)])
    bad = 0
    nan_bad = 0
    solved = 0
    do m = 1, 4
      do g = 1, ubound(mechs(m)%links, 1)
        mechs(m)%links(g) = assur_link_t(id=g, m=1.0_wp + 0.2_wp * g, j=0.01_wp * g, s=[0.04_wp * mod(g, 3), 0.01_wp])
      end do
      mechs(m)%g = 9.81_wp
      without%link_angles = .false.
      do k = 0, 23
        phi = (7.0_wp + 15.0_wp * k) * deg_to_rad
        call assur_step(mechs(m), phi, 20.0_wp, 3.0_wp, [real(wp) ::], [real(wp) ::], with, e1)
        call assur_step(mechs(m), phi, 20.0_wp, 3.0_wp, [real(wp) ::], [real(wp) ::], without, e2)
        if (allocated(e1) .neqv. allocated(e2)) bad = bad + 1
        if (allocated(e1) .or. allocated(e2)) cycle
        solved = solved + 1
        if (any(transfer(with%f, 0_i8, size(with%f)) /= transfer(without%f, 0_i8, size(without%f))) .or. &
            any(transfer(with%n, 0_i8, size(with%n)) /= transfer(without%n, 0_i8, size(without%n))) .or. &
            any(transfer(with%m, 0_i8, size(with%m)) /= transfer(without%m, 0_i8, size(without%m))) .or. &
            with%m1 /= without%m1 .or. with%m1_power /= without%m1_power .or. &
            with%residual /= without%residual .or. with%mismatch /= without%mismatch .or. &
            any(with%work_states%u /= without%work_states%u) .or. &
            any(with%work_states%cos_th /= without%work_states%cos_th)) bad = bad + 1
        select case (m)
        case (1)
          if (any(with%work_states([2, 3, 5])%th /= without%work_states([2, 3, 5])%th) .or. &
              .not. ieee_is_nan(without%work_states(4)%th)) nan_bad = nan_bad + 1
        case (4)
          if (.not. all(ieee_is_nan(without%work_states(2:3)%th))) nan_bad = nan_bad + 1
        case default
          if (any(with%work_states(2:5)%th /= without%work_states(2:5)%th)) nan_bad = nan_bad + 1
        end select
      end do
    end do
    call check_true(t, "without link angles: the same bits as with them (4 mechanisms, 24 angles)", bad == 0, &
                    int_str(bad)//" steps differ")
    call check_true(t, "without link angles: the angles a guide needs kept, RRR and RRP link a NaN", nan_bad == 0, &
                    int_str(nan_bad)//" steps differ")
    call check_true(t, "without link angles: at least 40 of 96 steps assembled", solved >= 40, int_str(solved))
  end subroutine test_link_angles_off

  ! ----------------------------------------------------------------------------------------
  !> Prescribed omega(k), eps(k): a crank with J about its pivot and massless, unloaded dyad
  !> needs M1 = J*eps1; with a heavy crank centre of mass off the pivot, gravity and
  !> d'Alembert loads give M1 = J_A*eps1 + m*g*x_S (y up), checked by hand.
  subroutine test_prescribed_speed_law(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_mech_t) :: mech
    type(assur_step_t) :: s
    type(error_t), allocatable :: error
    real(wp), parameter :: z2(2) = 0.0_wp, jc = 2.0_wp, mc = 3.0_wp, rs = 0.2_wp, g = 9.81_wp
    real(wp), parameter :: omega = 4.0_wp, eps = 3.0_wp
    real(wp) :: phi
    mech = make_mech([dyad(kind_rrr, [1, 0], reshape([0.1_wp, 0.0_wp, 0.35_wp, 0.05_wp], [2, 2]), &
                           [0.0_wp, 0.0_wp], 0.3_wp, 0.25_wp, 0.0_wp, 1, z2, 0.0_wp)])
    mech%links(1)%j = jc
    call assur_step(mech, 0.3_wp, omega, eps, [real(wp) ::], [real(wp) ::], s, error)
    call check_true(t, "prescribed law: solvable", .not. allocated(error), "error")
    call check_close(t, "prescribed law: M1 = J*eps1", jc * eps, s%m1, 1.0e-12_wp, 1.0e-12_wp)
    mech%links(1)%m = mc
    mech%links(1)%s = [rs, 0.0_wp]
    mech%g = g
    mech%down = [0.0_wp, -1.0_wp]
    phi = 0.3_wp
    call assur_step(mech, phi, omega, eps, [real(wp) ::], [real(wp) ::], s, error)
    call check_close(t, "prescribed law: M1 = (J + m r^2) eps1 + m g r cos(phi1)", &
                     (jc + mc * rs**2) * eps + mc * g * rs * cos(phi), s%m1, 1.0e-12_wp, 1.0e-12_wp)
    call check_close(t, "prescribed law: power balance", s%m1_power, s%m1, 1.0e-12_wp, 1.0e-12_wp)
  end subroutine test_prescribed_speed_law

  !> Force windows are absolute crank angles (not modulo 360), ends included.
  subroutine test_window(t)
    type(test_counts_t), intent(inout) :: t
    call check_close(t, "window inside", 3.0_wp, assur_window(100.0_wp, 95.0_wp, 265.0_wp, 3.0_wp, 1.0_wp), 0.0_wp, 0.0_wp)
    call check_close(t, "window at end", 3.0_wp, assur_window(265.0_wp, 95.0_wp, 265.0_wp, 3.0_wp, 1.0_wp), 0.0_wp, 0.0_wp)
    call check_close(t, "window outside", 1.0_wp, assur_window(270.0_wp, 95.0_wp, 265.0_wp, 3.0_wp, 1.0_wp), 0.0_wp, 0.0_wp)
    call check_close(t, "window not modulo 360", 1.0_wp, assur_window(455.0_wp, 95.0_wp, 265.0_wp, 3.0_wp, 1.0_wp), &
                     0.0_wp, 0.0_wp)
  end subroutine test_window

end module test_assur
