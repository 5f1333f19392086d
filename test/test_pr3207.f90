!> PR 3207 tests: kinematics against finite differences, self-check on the reference deck,
!> hand-checkable statics (cutting force only; gravity only), the two-value force window.
module test_pr3207
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_pr3207, only: pr3207_params_t, pr3207_position_t, pr3207_step_t, &
    pr3207_position, pr3207_step
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, pr3207_cut_force
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_pr3207_layout, only: pr3207_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_pr3207_tests

  !> The spec's reference data.
  type(pr3207_params_t), parameter :: ref = pr3207_params_t(l_ab=0.11_wp, l_ac=0.38_wp, l_cd=0.72_wp, &
    l_cs3=0.36_wp, m1=12.0_wp, m3=22.0_wp, m5=60.0_wp, j3=1.1_wp, omega1=7.5_wp, g=9.81_wp)

contains

  subroutine run_pr3207_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_finite_differences(t)
    call test_reference_selfcheck(t)
    call test_cutting_force_statics(t)
    call test_gravity_statics(t)
    call test_cut_window(t)
  end subroutine run_pr3207_tests

  !> u31, eps31, l_CB', S3 and ram analogues against central differences of positions.
  subroutine test_finite_differences(t)
    type(test_counts_t), intent(inout) :: t
    !> FD step, rad; truncation ~h^2 ~ 1e-8, roundoff of 2nd differences ~1e-16/h^2 ~ 1e-8.
    real(wp), parameter :: h = 1.0e-4_wp
    !> Tolerances: relative 1e-6, absolute 1e-7 (m/rad or rad/rad).
    real(wp), parameter :: rtol = 1.0e-6_wp, atol = 1.0e-7_wp
    real(wp), parameter :: angles_deg(*) = [5.0_wp, 47.0_wp, 73.17_wp, 100.0_wp, 181.0_wp, 250.0_wp, 333.0_wp]
    type(pr3207_position_t) :: p0, pm, pp
    character(len=32) :: at
    integer :: i, c
    do i = 1, size(angles_deg)
      write (at, '(" at phi1=",f7.2)') angles_deg(i)
      p0 = pr3207_position(ref, angles_deg(i) * deg_to_rad)
      pm = pr3207_position(ref, angles_deg(i) * deg_to_rad - h)
      pp = pr3207_position(ref, angles_deg(i) * deg_to_rad + h)
      call check_close(t, "u31"//trim(at), (pp%phi3 - pm%phi3) / (2 * h), p0%u31, rtol, atol)
      call check_close(t, "eps31"//trim(at), (pp%phi3 - 2 * p0%phi3 + pm%phi3) / h**2, p0%eps31, rtol, atol)
      call check_close(t, "l_cb'"//trim(at), (pp%l_cb - pm%l_cb) / (2 * h), p0%dl_cb, rtol, atol)
      call check_close(t, "v5q"//trim(at), (pp%y5 - pm%y5) / (2 * h), p0%v5q, rtol, atol)
      call check_close(t, "a5q"//trim(at), (pp%y5 - 2 * p0%y5 + pm%y5) / h**2, p0%a5q, rtol, atol)
      do c = 1, 2
        call check_close(t, "v_s3q"//trim(at), (pp%s3(c) - pm%s3(c)) / (2 * h), p0%v_s3q(c), rtol, atol)
        call check_close(t, "a_s3q"//trim(at), (pp%s3(c) - 2 * p0%s3(c) + pm%s3(c)) / h**2, p0%a_s3q(c), rtol, atol)
      end do
      call check_close(t, "phi3 quadrant II/III"//trim(at), 1.0_wp, &
                       merge(1.0_wp, 0.0_wp, cos(p0%phi3) < 0.0_wp), 0.0_wp, 0.0_wp)
    end do
  end subroutine test_finite_differences

  !> Every step of data/pr3207.nml: equilibrium residual and power balance <= 1e-9.
  subroutine test_reference_selfcheck(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: limit = 1.0e-9_wp
    type(pr3207_deck_t) :: deck
    type(pr3207_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    character(len=64) :: detail
    integer :: k
    call load_deck("data/pr3207.nml", source, error)
    if (.not. allocated(error)) call read_pr3207_deck(source, deck, error)
    call check_true(t, "read data/pr3207.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    call check_true(t, "reference deck has 13 steps", deck%n == 13, "wrong step count")
    call pr3207_solve(deck, steps)
    do k = 1, size(steps)
      write (detail, '("step ",i0,": ",es10.3)') k, steps(k)%residual
      call check_true(t, "pr3207 equilibrium residual <= 1e-9", steps(k)%residual <= limit, trim(detail))
      write (detail, '("step ",i0,": ",es10.3)') k, steps(k)%mismatch
      call check_true(t, "pr3207 M1 power balance <= 1e-9", steps(k)%mismatch <= limit, trim(detail))
      call check_close(t, "pr3207 M1 vs power balance", steps(k)%m1_power, steps(k)%m1, limit, limit)
    end do
  end subroutine test_reference_selfcheck

  !> omega1 = 0, g = 0, only a cutting force F: the lever rule by hand.
  !> phi1 = 90: B = (0, l_AB), l_CB^2 = l_AC^2 + l_AB^2, M1 = F*l_CD*l_AC*l_AB^2/l_CB^3.
  !> phi1 = 0: the lever lies along -x, M1 = -F*l_CD*l_AB/(l_AC - l_AB).
  subroutine test_cutting_force_statics(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: f = 1000.0_wp, rtol = 1.0e-12_wp, atol = 1.0e-9_wp
    type(pr3207_params_t) :: p
    type(pr3207_step_t) :: s
    real(wp) :: l_cb, n
    p = ref
    p%omega1 = 0.0_wp
    p%g = 0.0_wp
    s = pr3207_step(p, 90.0_wp * deg_to_rad, f)
    l_cb = hypot(p%l_ac, p%l_ab)
    call check_close(t, "statics phi1=90: M1 by lever rule", f * p%l_cd * p%l_ac * p%l_ab**2 / l_cb**3, s%m1, rtol, atol)
    ! block force normal to the lever: N = F*l_CD*|cos(phi3)|/l_CB with cos(phi3) = -l_AC/l_CB
    n = f * p%l_cd * p%l_ac / l_cb**2
    call check_close(t, "statics phi1=90: |F21|", n, hypot(s%f21(1), s%f21(2)), rtol, atol)
    call check_close(t, "statics phi1=90: F34 = F", f, s%f34(2), rtol, atol)
    call check_close(t, "statics phi1=90: F16 = F21 (no weight)", s%f21(1), s%f16(1), rtol, atol)
    call check_close(t, "statics phi1=90: F56 = 0", 0.0_wp, hypot(s%f56(1), s%f56(2)), 0.0_wp, atol)
    call check_close(t, "statics phi1=90: frame takes F (x)", 0.0_wp, s%f16(1) + s%f36(1) + s%f56(1), 0.0_wp, atol)
    call check_close(t, "statics phi1=90: frame takes F (y)", -f, s%f16(2) + s%f36(2) + s%f56(2), rtol, atol)
    s = pr3207_step(p, 0.0_wp, f)
    call check_close(t, "statics phi1=0: M1 by lever rule", -f * p%l_cd * p%l_ab / (p%l_ac - p%l_ab), s%m1, rtol, atol)
  end subroutine test_cutting_force_statics

  !> omega1 = 0, no cutting force, gravity only (along +x).
  !> phi1 = 90: N*l_CB = m3*g*l_CS3*sin(phi3), sin(phi3) = l_AB/l_CB, B.e3 = l_AB^2/l_CB
  !> => M1 = m3*g*l_CS3*l_AB^3/l_CB^3; the frame carries the whole weight.
  subroutine test_gravity_statics(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-12_wp, atol = 1.0e-9_wp
    type(pr3207_params_t) :: p
    type(pr3207_step_t) :: s
    real(wp) :: l_cb, weight
    p = ref
    p%omega1 = 0.0_wp
    s = pr3207_step(p, 90.0_wp * deg_to_rad, 0.0_wp)
    l_cb = hypot(p%l_ac, p%l_ab)
    weight = (p%m1 + p%m3 + p%m5) * p%g
    call check_close(t, "gravity phi1=90: M1", p%m3 * p%g * p%l_cs3 * p%l_ab**3 / l_cb**3, s%m1, rtol, atol)
    call check_close(t, "gravity phi1=90: F56 = -m5 g", -p%m5 * p%g, s%f56(1), rtol, atol)
    call check_close(t, "gravity phi1=90: F34 = 0", 0.0_wp, s%f34(2), 0.0_wp, atol)
    call check_close(t, "gravity: frame carries all weight (x)", -weight, s%f16(1) + s%f36(1) + s%f56(1), rtol, atol)
    call check_close(t, "gravity: frame carries all weight (y)", 0.0_wp, s%f16(2) + s%f36(2) + s%f56(2), 0.0_wp, atol)
    s = pr3207_step(p, 0.0_wp, 0.0_wp)
    call check_close(t, "gravity phi1=0: lever hangs through C, M1 = 0", 0.0_wp, s%m1, 0.0_wp, atol)
    call check_close(t, "gravity phi1=0: F16 = -G1", -p%m1 * p%g, s%f16(1), rtol, atol)
  end subroutine test_gravity_statics

  !> The two-value form's angle window, also across 360.
  subroutine test_cut_window(t)
    type(test_counts_t), intent(inout) :: t
    call window(t, "[95,265] at 95", 95.0_wp, 95.0_wp, 265.0_wp, 3.0_wp)
    call window(t, "[95,265] at 265", 265.0_wp, 95.0_wp, 265.0_wp, 3.0_wp)
    call window(t, "[95,265] at 270", 270.0_wp, 95.0_wp, 265.0_wp, 1.0_wp)
    call window(t, "[95,265] at 455", 455.0_wp, 95.0_wp, 265.0_wp, 3.0_wp)
    call window(t, "[300,60] at 0", 0.0_wp, 300.0_wp, 60.0_wp, 3.0_wp)
    call window(t, "[300,60] at 100", 100.0_wp, 300.0_wp, 60.0_wp, 1.0_wp)
    call window(t, "[0,360] at 200", 200.0_wp, 0.0_wp, 360.0_wp, 3.0_wp)
  end subroutine test_cut_window

  !> Work force 3, idle force 1: `expected` is the one that must be chosen.
  subroutine window(t, name, phi, start, end, expected)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name
    real(wp), intent(in) :: phi, start, end, expected
    call check_close(t, "cut window "//name, expected, pr3207_cut_force(phi, start, end, 3.0_wp, 1.0_wp), 0.0_wp, 0.0_wp)
  end subroutine window

end module test_pr3207
