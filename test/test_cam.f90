!> Cam tests: hand cases of the translating and flat-faced follower, the self-locking
!> (jamming) threshold at the analytic critical pressure angle / contact offset, flags,
!> self-checks of the example decks.
module test_cam
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
  use kinetostat_cam, only: cam_params_t, cam_step_t, cam_step, cam_critical_angle
  use kinetostat_cam_deck, only: cam_deck_t, read_cam_deck
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_cam_layout, only: cam_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_cam_tests

  !> Tolerances of the hand cases: relative 1e-12, absolute 1e-9 N.
  real(wp), parameter :: rtol = 1.0e-12_wp, atol = 1.0e-9_wp

contains

  subroutine run_cam_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_translating_hand(t)
    call test_no_friction(t)
    call test_critical_angle(t)
    call test_flags(t)
    call test_flat_hand(t)
    call test_flat_critical_offset(t)
    call test_example_decks(t)
  end subroutine run_cam_tests

  !> l = 0.04, a = 0.05, f = 0.3, theta = 20 deg, F2 = 320 N, rise:
  !> N = F2/(cos th - f sin th (l + 2a)/l) = 320/(0.9396926 - 0.3*0.3420201*3.5) = 551.1806 N,
  !> R_C = -N sin th (l + a)/l, R_D = N sin th a/l (lateral), friction f|R| against the motion.
  subroutine test_translating_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    real(wp) :: n, sn, cs
    p = cam_params_t(l=0.04_wp, a=0.05_wp, f=0.3_wp)
    s = cam_step(p, 20.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, 320.0_wp, 1.0_wp)
    sn = 0.3420201433256687_wp
    cs = 0.9396926207859084_wp
    n = 320.0_wp / (cs - 0.3_wp * sn * 3.5_wp)
    call check_close(t, "cam N by hand", n, s%n, 1.0e-12_wp, atol)
    call check_close(t, "cam F21 = N (sin, cos)", n * sn, s%f21(1), 1.0e-12_wp, atol)
    call check_close(t, "cam R_C = -N sin (l+a)/l", -n * sn * 2.25_wp, s%f23c(1), 1.0e-12_wp, atol)
    call check_close(t, "cam R_D = N sin a/l", n * sn * 1.25_wp, s%f23d(1), 1.0e-12_wp, atol)
    call check_close(t, "cam friction at C opposes the rise", -0.3_wp * n * sn * 2.25_wp, s%f23c(2), 1.0e-12_wp, atol)
    call check_close(t, "cam friction at D opposes the rise", -0.3_wp * n * sn * 1.25_wp, s%f23d(2), 1.0e-12_wp, atol)
    call check_close(t, "cam K_F = N/F2", n / 320.0_wp, s%kf, 1.0e-12_wp, 0.0_wp)
    call check_true(t, "cam hand case: no flags", .not. (s%jammed .or. s%lost .or. s%kf_over), "flag set")
    call check_true(t, "cam hand case self-check", s%residual <= 1.0e-12_wp .and. s%mismatch <= 1.0e-12_wp, "too large")
    ! return stroke: friction helps, N = F2/(cos + f sin (l+2a)/l)
    s = cam_step(p, -20.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, 320.0_wp, -1.0_wp)
    call check_close(t, "cam return N by hand", 320.0_wp / (cs + 0.3_wp * sn * 3.5_wp), s%n, 1.0e-12_wp, atol)
    call check_close(t, "cam return friction at C points up", 0.3_wp * s%n * sn * 2.25_wp, s%f23c(2), 1.0e-12_wp, atol)
    call check_close(t, "cam return F21x < 0 for theta < 0", -s%n * sn, s%f21(1), 1.0e-12_wp, atol)
  end subroutine test_translating_hand

  !> f = 0: N = F2/cos(theta), and the guide reactions balance the lateral force.
  subroutine test_no_friction(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    p = cam_params_t(l=0.1_wp, a=0.02_wp, f=0.0_wp)
    s = cam_step(p, 60.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_close(t, "cam f=0: N = F2/cos(60)", 200.0_wp, s%n, 1.0e-12_wp, atol)
    call check_close(t, "cam f=0: R_C + R_D = -N sin", -200.0_wp * sin(60.0_wp * deg_to_rad), &
                     s%f23c(1) + s%f23d(1), 1.0e-12_wp, atol)
    call check_close(t, "cam f=0: theta_cr = 90", 90.0_wp, cam_critical_angle(p) * rad_to_deg, 1.0e-14_wp, 0.0_wp)
  end subroutine test_no_friction

  !> Self-locking on the rise starts at tan(theta_cr) = l/(f (l + 2a)) (docs/gears-cams.md derivation):
  !> l = 0.04, a = 0.05, f = 0.3 -> theta_cr = atan(0.04/0.042) = 43.60281897 deg.
  subroutine test_critical_angle(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    real(wp) :: th_cr
    real(wp), parameter :: d = 1.0e-6_wp * deg_to_rad
    p = cam_params_t(l=0.04_wp, a=0.05_wp, f=0.3_wp)
    th_cr = cam_critical_angle(p)
    call check_close(t, "theta_cr = atan(l/(f(l+2a)))", atan(0.04_wp / 0.042_wp) * rad_to_deg, &
                     th_cr * rad_to_deg, 1.0e-14_wp, 0.0_wp)
    call check_close(t, "theta_cr value, deg", 43.60281897_wp, th_cr * rad_to_deg, 1.0e-9_wp, 0.0_wp)
    s = cam_step(p, th_cr - d, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "not jammed just below theta_cr", .not. s%jammed .and. s%n > 1.0e6_wp, "jammed or small N")
    s = cam_step(p, th_cr, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "jammed at theta_cr", s%jammed .and. s%n == 0.0_wp, "not jammed")
    s = cam_step(p, th_cr + d, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "jammed just above theta_cr", s%jammed, "not jammed")
    s = cam_step(p, -(th_cr + d), 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "jammed at -theta_cr (sign of theta irrelevant)", s%jammed, "not jammed")
    s = cam_step(p, 80.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, 100.0_wp, -1.0_wp)
    call check_true(t, "return stroke never jams", .not. s%jammed .and. s%n > 0.0_wp, "jammed")
    ! longer guide, shorter overhang: higher critical angle
    p = cam_params_t(l=0.1_wp, a=0.0_wp, f=0.2_wp)
    th_cr = cam_critical_angle(p)
    call check_close(t, "theta_cr with a = 0: atan(1/f)", atan(5.0_wp), th_cr, 1.0e-14_wp, 0.0_wp)
    s = cam_step(p, th_cr - 1.0e-4_wp, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "a = 0: free below theta_cr", .not. s%jammed, "jammed")
    s = cam_step(p, th_cr + 1.0e-4_wp, 0.0_wp, 0.0_wp, 100.0_wp, 1.0_wp)
    call check_true(t, "a = 0: jammed above theta_cr", s%jammed, "free")
  end subroutine test_critical_angle

  !> K_F > 2 threshold and contact loss.
  !> K_F = 2 where cos th - f k sin th = 1/2 with k = (l+2a)/l; l = 0.04, a = 0.05, f = 0.3.
  subroutine test_flags(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    real(wp) :: c, th2, r
    p = cam_params_t(l=0.04_wp, a=0.05_wp, f=0.3_wp)
    c = 0.3_wp * 3.5_wp
    ! cos th - c sin th = R cos(th + atan c) = 1/2
    r = hypot(1.0_wp, c)
    th2 = acos(0.5_wp / r) - atan(c)
    s = cam_step(p, th2 - 1.0e-6_wp, 0.0_wp, 0.0_wp, 50.0_wp, 1.0_wp)
    call check_true(t, "K_F just below 2: no flag", .not. s%kf_over .and. s%kf < 2.0_wp, "flagged")
    s = cam_step(p, th2 + 1.0e-6_wp, 0.0_wp, 0.0_wp, 50.0_wp, 1.0_wp)
    call check_true(t, "K_F just above 2: flag", s%kf_over .and. s%kf > 2.0_wp, "not flagged")
    s = cam_step(p, 10.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, -5.0_wp, 1.0_wp)
    call check_true(t, "F2 < 0: contact lost", s%lost .and. .not. s%jammed .and. s%n == 0.0_wp, "not flagged")
    s = cam_step(p, 10.0_wp * deg_to_rad, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp)
    call check_true(t, "F2 = 0: contact lost (F2 > 0 required)", s%lost, "not flagged")
  end subroutine test_flags

  !> Flat face, CCW cam (mu_cam = -f_cam), rise with x_B = 0.02 m: l = 0.05, a = 0.03,
  !> f = 0.12, f_cam = 0.1. Unit cam force c = (-0.1, 1); moment arm x_B + a*mu = 0.017 m;
  !> R_D/N = 0.34, R_C/N = 0.1 - 0.34 = -0.24; N = F2/(1 - 0.12*(0.24 + 0.34)) = 500/0.9304.
  subroutine test_flat_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    real(wp) :: n
    p = cam_params_t(l=0.05_wp, a=0.03_wp, f=0.12_wp)
    s = cam_step(p, 0.0_wp, 0.02_wp, -0.1_wp, 500.0_wp, 1.0_wp)
    n = 500.0_wp / 0.9304_wp
    call check_close(t, "flat N by hand", n, s%n, 1.0e-12_wp, atol)
    call check_close(t, "flat R_D by hand", 0.34_wp * n, s%f23d(1), 1.0e-12_wp, atol)
    call check_close(t, "flat R_C by hand", -0.24_wp * n, s%f23c(1), 1.0e-12_wp, atol)
    call check_close(t, "flat cam friction = -f_cam N", -0.1_wp * n, s%f21(1), 1.0e-12_wp, atol)
    call check_close(t, "flat K_F = |F21|/F2", n * sqrt(1.01_wp) / 500.0_wp, s%kf, 1.0e-12_wp, 0.0_wp)
    ! no friction anywhere, offset contact: N = F2, R_D = -R_C = F2 x_B / l
    p%f = 0.0_wp
    s = cam_step(p, 0.0_wp, 0.01_wp, 0.0_wp, 500.0_wp, 1.0_wp)
    call check_close(t, "flat f=0: N = F2", 500.0_wp, s%n, 1.0e-12_wp, atol)
    call check_close(t, "flat f=0: R_D = F2 x_B/l", 100.0_wp, s%f23d(1), 1.0e-12_wp, atol)
    call check_close(t, "flat f=0: R_C = -R_D", -100.0_wp, s%f23c(1), 1.0e-12_wp, atol)
  end subroutine test_flat_hand

  !> Flat face, no cam friction: the rise jams when the contact offset reaches x_cr = l/(2f).
  subroutine test_flat_critical_offset(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_params_t) :: p
    type(cam_step_t) :: s
    real(wp) :: x_cr
    p = cam_params_t(l=0.05_wp, a=0.03_wp, f=0.2_wp)
    x_cr = p%l / (2.0_wp * p%f)
    s = cam_step(p, 0.0_wp, x_cr * (1.0_wp - 1.0e-7_wp), 0.0_wp, 10.0_wp, 1.0_wp)
    call check_true(t, "flat: free just below x_cr = l/(2f)", .not. s%jammed, "jammed")
    s = cam_step(p, 0.0_wp, x_cr * (1.0_wp + 1.0e-7_wp), 0.0_wp, 10.0_wp, 1.0_wp)
    call check_true(t, "flat: jammed just above x_cr = l/(2f)", s%jammed, "free")
    s = cam_step(p, 0.0_wp, -x_cr * (1.0_wp + 1.0e-7_wp), 0.0_wp, 10.0_wp, 1.0_wp)
    call check_true(t, "flat: jammed at -x_cr too", s%jammed, "free")
  end subroutine test_flat_critical_offset

  !> Both example decks: residual and N mismatch <= 1e-9 at every computed step.
  subroutine test_example_decks(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: decks(2) = [character(len=24) :: "data/cam_translating.nml", "data/cam_flat.nml"]
    type(cam_deck_t) :: deck
    type(cam_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    integer :: i
    do i = 1, size(decks)
      call load_deck(trim(decks(i)), source, error)
      if (.not. allocated(error)) call read_cam_deck(source, deck, error)
      call check_true(t, "read "//trim(decks(i)), .not. allocated(error), "deck rejected")
      if (allocated(error)) cycle
      call cam_solve(deck, steps)
      call check_true(t, trim(decks(i))//" residual <= 1e-9", maxval(steps%residual) <= 1.0e-9_wp, "too large")
      call check_true(t, trim(decks(i))//" N mismatch <= 1e-9", maxval(steps%mismatch) <= 1.0e-9_wp, "too large")
    end do
    call load_deck("data/cam_translating.nml", source, error)
    if (.not. allocated(error)) call read_cam_deck(source, deck, error)
    if (allocated(error)) return
    call cam_solve(deck, steps)
    call check_true(t, "translating deck: step 4 (45 deg > theta_cr) jammed", steps(4)%jammed, "not jammed")
    call check_true(t, "translating deck: step 11 (F2 < 0) lost", steps(11)%lost, "not lost")
    call check_true(t, "translating deck: steps 3 and 5 K_F > 2", steps(3)%kf_over .and. steps(5)%kf_over, "no flag")
  end subroutine test_example_decks

end module test_cam
