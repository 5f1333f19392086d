!> Tests of the generic engine's extensions for other people's mechanisms: a linear actuator
!> as driver (data/assur_pr3050.nml against the dedicated PR 3050 program, a perturbed deck
!> rejected by the same comparison; F_drive by the power balance of a slider-crank driven
!> by its slider); load tables over a link's position checked by hand.
module test_assur_ext
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_vec2, only: magnitude
  use kinetostat_text, only: real_str
  use kinetostat_deck, only: deck_source_t, load_deck, deck_source_from_text
  use kinetostat_assur, only: assur_step_t, pair_index, crank_pin_index
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, assur_phi1_deg, assur_omega1, assur_load_value
  use kinetostat_assur_layout, only: assur_solve
  use kinetostat_pr3050, only: pr3050_step_t, pr3050_step
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck, pr3050_phi3_deg
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_assur_ext_tests

contains

  subroutine run_assur_ext_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_pr3050_vs_dedicated(t)
    call test_actuator_slider_crank(t)
    call test_load_table_by_hand(t)
  end subroutine run_assur_ext_tests

  !> Largest relative difference (to the step's largest force) between the generic PR 3050
  !> deck's F14, F34, F32 = -F23 (vectors) and F_drive and the dedicated program's F14, F34,
  !> F32 and F2, over every step; -1 when a deck fails.
  real(wp) function pr3050_difference(generic_text) result(worst)
    !> The generic deck's text.
    character(*), intent(in) :: generic_text
    type(assur_deck_t) :: generic
    type(pr3050_deck_t) :: dedicated
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    type(assur_step_t), allocatable :: steps(:)
    type(pr3050_step_t) :: ref
    real(wp) :: scale, diff
    integer :: k
    worst = -1.0_wp
    call load_deck("data/pr3050.nml", source, error)
    if (.not. allocated(error)) call read_pr3050_deck(source, dedicated, error)
    if (allocated(error)) return
    call deck_source_from_text("generic", generic_text, source)
    call read_assur_deck(source, generic, error)
    if (allocated(error)) return
    call assur_solve("generic", generic, steps, error)
    if (allocated(error)) return
    if (size(steps) /= dedicated%n) return
    worst = 0.0_wp
    do k = 1, dedicated%n
      ref = pr3050_step(dedicated%p, pr3050_phi3_deg(dedicated, k) * deg_to_rad, dedicated%omega3(k), dedicated%eps3(k))
      associate (s => steps(k))
        scale = max(magnitude(ref%f14), magnitude(ref%f34), magnitude(ref%f32), abs(ref%f2))
        diff = max(magnitude(s%f(:, pair_index(1, 1)) - ref%f14), magnitude(s%f(:, crank_pin_index(1)) - ref%f34), &
                   magnitude(-s%f(:, pair_index(1, 3)) - ref%f32), abs(s%f_drive - ref%f2))
        worst = max(worst, diff / scale)
      end associate
    end do
  end function pr3050_difference

  !> data/assur_pr3050.nml (rocker as input link, cylinder-rod pair as actuator) equals the
  !> dedicated program's F14, F34, F32 and F2 to relative 1e-9 at every step; the same
  !> comparison rejects a deck whose rod centre of mass is 1 mm off.
  subroutine test_pr3050_vs_dedicated(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    character(len=:), allocatable :: text, perturbed
    real(wp) :: worst
    character(len=80) :: detail
    integer :: i, at
    call load_deck("data/assur_pr3050.nml", source, error)
    if (allocated(error)) then
      call check_true(t, "load data/assur_pr3050.nml", .false., error%message)
      return
    end if
    text = ""
    do i = 1, size(source%lines)
      text = text//trim(source%lines(i))//new_line("a")
    end do
    worst = pr3050_difference(text)
    write (detail, '("largest relative difference ",es10.3)') worst
    call check_true(t, "assur_pr3050 = dedicated PR 3050 (F14, F34, F32, F2) to 1e-9", &
                    worst >= 0.0_wp .and. worst <= 1.0e-9_wp, trim(detail))
    at = index(text, "dyad(1)%s3 = 0.48, 0")
    call check_true(t, "assur_pr3050 deck has the rod's centre of mass", at > 0, "line not found")
    if (at == 0) return
    perturbed = text(:at - 1)//"dyad(1)%s3 = 0.481, 0"//text(at + len("dyad(1)%s3 = 0.48, 0"):)
    worst = pr3050_difference(perturbed)
    write (detail, '("largest relative difference ",es10.3)') worst
    call check_true(t, "assur_pr3050 comparison rejects a deck with S2 1 mm off", worst > 1.0e-9_wp, trim(detail))
  end subroutine test_pr3050_vs_dedicated

  !> A massless slider-crank driven by its slider (an actuator in the RRP dyad's pair 3, the
  !> slider on the frame guide along +x) against a moment M = 7 N*m on the crank: by virtual
  !> work M + F_drive*s' = 0 with the stroke s = x_B in closed form; no balancing moment.
  subroutine test_actuator_slider_crank(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    real(wp), parameter :: r = 0.1_wp, l = 0.35_wp, m_load = 7.0_wp
    real(wp) :: phi, sth, cth, ds, s
    character(len=40) :: at
    integer :: k
    call deck_source_from_text("actuated", "&assur"//new_line("a")// &
      "  omega1 = 10, g = 0, phi_start = 15, dphi = 30, n = 6"//new_line("a")// &
      "  dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3, dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0"// &
      new_line("a")//"  dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0, dyad(1)%angle3 = 0, dyad(1)%l2 = 0.35"// &
      new_line("a")//"  moment(1)%link = 1, moment(1)%value = 7"//new_line("a")// &
      "  drive_dyad = 1, drive_pair = 3"//new_line("a")//"/", source)
    call read_assur_deck(source, deck, error)
    if (.not. allocated(error)) call assur_solve("actuated", deck, steps, error)
    if (allocated(error)) then
      call check_true(t, "actuated slider-crank", .false., error%message)
      return
    end if
    do k = 1, size(steps)
      phi = assur_phi1_deg(deck, k) * deg_to_rad
      ! x_B = r cos(phi) + l cos(th), sin(th) = -r sin(phi)/l, th' = -r cos(phi)/(l cos(th))
      sth = -r * sin(phi) / l
      cth = sqrt(1.0_wp - sth**2)
      s = r * cos(phi) + l * cth
      ds = -r * sin(phi) + r * cos(phi) * sth / cth
      write (at, '(" at phi1=",f6.1)') assur_phi1_deg(deck, k)
      ! virtual work: M*1 + F_drive*ds = 0 (massless links, no gravity)
      call check_close(t, "actuated slider-crank: F_drive = -M/stroke'"//trim(at), -m_load / ds, steps(k)%f_drive, &
                       1.0e-12_wp, 0.0_wp)
      call check_close(t, "actuated slider-crank: stroke"//trim(at), s, steps(k)%stroke, 1.0e-12_wp, 0.0_wp)
      call check_close(t, "actuated slider-crank: stroke speed"//trim(at), ds * 10.0_wp, steps(k)%stroke_v, &
                       1.0e-12_wp, 1.0e-12_wp)
      call check_close(t, "actuated slider-crank: no balancing moment"//trim(at), 0.0_wp, steps(k)%m1, 0.0_wp, 0.0_wp)
      call check_true(t, "actuated slider-crank: self-check"//trim(at), &
                      steps(k)%residual <= 1.0e-9_wp .and. steps(k)%mismatch <= 1.0e-12_wp, &
                      "residual above 1e-9 or mismatch above 1e-12: residual "//real_str(steps(k)%residual)// &
                      ", mismatch "//real_str(steps(k)%mismatch))
    end do
  end subroutine test_actuator_slider_crank

  !> Load tables over the slider's position on data/assur_slider_crank.nml, by hand: the
  !> slider B = (x, e) with x = r cos(phi) + sqrt(l^2 - (e - r sin(phi))^2) (its stroke from
  !> the guide point (0, e)); a linear table F = 2000*(x - 0.2) N and a triangle 0 at 0.2 m,
  !> 300 N at 0.35 m, 0 at 0.5 m; a moment table over the rod's angle (deg, modulo 360).
  subroutine test_load_table_by_hand(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: r = 0.1_wp, l = 0.35_wp, e = 0.02_wp
    character(len=*), parameter :: window = "force(1)%value = 500, force(1)%idle = 100, force(1)%phi_on = 0, "// &
      "force(1)%phi_off = 180"
    type(assur_deck_t) :: deck
    type(error_t), allocatable :: error
    real(wp) :: phi, x, expected, th
    character(len=40) :: at
    integer :: k, variant
    character(len=:), allocatable :: replacement
    do variant = 1, 3
      select case (variant)
      case (1)
        replacement = "force(1)%table = 0.2, 0, 0.5, 600"
      case (2)
        replacement = "force(1)%table = 0.2, 0, 0.35, 300, 0.5, 0"
      case default
        replacement = "force(1)%value = 500, moment(1)%link = 2, moment(1)%over = 2, "// &
          "moment(1)%table = -90, -9, 90, 9"
      end select
      call read_edited("data/assur_slider_crank.nml", window, replacement, deck, error)
      if (allocated(error)) then
        call check_true(t, "load table deck "//replacement, .false., error%message)
        cycle
      end if
      do k = 1, deck%n
        phi = assur_phi1_deg(deck, k) * deg_to_rad
        x = r * cos(phi) + sqrt(l**2 - (e - r * sin(phi))**2)
        write (at, '(" at phi1=",f6.1)') assur_phi1_deg(deck, k)
        select case (variant)
        case (1)
          expected = 2000.0_wp * (x - 0.2_wp)
          call check_close(t, "linear load table"//trim(at), expected, assur_load_value(deck, deck%force_load(1), k), &
                           1.0e-12_wp, 1.0e-12_wp)
        case (2)
          expected = 300.0_wp * (1.0_wp - abs(x - 0.35_wp) / 0.15_wp)
          call check_close(t, "triangle load table"//trim(at), expected, assur_load_value(deck, deck%force_load(1), k), &
                           1.0e-12_wp, 1.0e-12_wp)
        case default
          ! rod angle th: sin(th) = (e - r sin(phi))/l, |th| < 90 deg: M = 0.1 N*m per deg
          th = asin((e - r * sin(phi)) / l) * 180.0_wp / acos(-1.0_wp)
          call check_close(t, "moment table over the rod's angle"//trim(at), 0.1_wp * th, &
                           assur_load_value(deck, deck%moment_load(1), k), &
                           1.0e-12_wp, 1.0e-12_wp)
        end select
      end do
    end do
  end subroutine test_load_table_by_hand

  !> Read deck `path` with the first `old` replaced by `new`.
  subroutine read_edited(path, old, new, deck, error)
    character(*), intent(in) :: path, old, new
    type(assur_deck_t), intent(out) :: deck
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source
    character(len=:), allocatable :: text
    integer :: i, at
    call load_deck(path, source, error)
    if (allocated(error)) return
    text = ""
    do i = 1, size(source%lines)
      text = text//trim(source%lines(i))//new_line("a")
    end do
    at = index(text, old)
    if (at > 0) text = text(:at - 1)//new//text(at + len(old):)
    call deck_source_from_text(path, text, source)
    call read_assur_deck(source, deck, error)
  end subroutine read_edited

end module test_assur_ext
