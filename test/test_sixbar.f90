!> T.FTN (sixbar) tests: the manual's worked example at phi1 = 66.8 deg (printed digits and
!> exact values), the eps_q2 erratum switch, finite differences of every transfer function
!> over a full turn, self-check on the reference deck, hand statics, global equilibrium
!> across the two frames, the extreme position, assemblability.
module test_sixbar
  use kinetostat_kinds, only: wp, pi, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_vec2, only: unit_at, cross
  use kinetostat_sixbar, only: sixbar_params_t, sixbar_position_t, sixbar_step_t, sixbar_position, &
    sixbar_step, sixbar_extreme_phi1, sixbar_frame2_to_frame1, sixbar_frame1_to_frame2, sixbar_down1, &
    sixbar_down2, sixbar_ok, sixbar_open1, sixbar_open2
  use kinetostat_sixbar_deck, only: sixbar_deck_t, read_sixbar_deck
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_sixbar_layout, only: sixbar_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_sixbar_tests

  !> The data of the manual's worked example (section 2) with g = 10 as the example uses.
  type(sixbar_params_t), parameter :: ref = sixbar_params_t(a=0.170_wp, b=0.340_wp, l1=0.100_wp, &
    lam2=4.0_wp, lam_s2=0.5_wp, lam3=3.0_wp, lam_de=3.0_wp, lam4=2.0_wp, lam_s4=0.5_wp, lam_e=2.5_wp, &
    m1=50.0_wp, m2=5.0_wp, m3=8.0_wp, m4=2.0_wp, m5=6.0_wp, j1=20.0_wp, j2=0.01_wp, j3=0.2_wp, &
    j4=0.007_wp, omega1=100.0_wp, g=10.0_wp, legacy_eq2=.false.)
  !> Crank angle of the worked example, deg (frame 1).
  real(wp), parameter :: phi_example = 66.8_wp
  !> Slider load of the worked example, N (along +x2).
  real(wp), parameter :: f5_example = 1000.0_wp

contains

  subroutine run_sixbar_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_example_printed(t)
    call test_example_exact(t)
    call test_erratum(t)
    call test_finite_differences(t)
    call test_reference_selfcheck(t)
    call test_sweep_selfcheck(t)
    call test_slider_load_statics(t)
    call test_gravity_statics(t)
    call test_global_balance(t)
    call test_frames(t)
    call test_extreme(t)
    call test_assembly(t)
  end subroutine run_sixbar_tests

  !> The values the manual prints for phi1 = 66.8 deg, g = 10. The 1991 printout is
  !> consistent with exact physics only to about 1e-3 (its phi4 is 0.015 deg low, which
  !> moves M_54E, F56 and F54y by 0.4 %); tolerances: kinematics relative 2e-3 (angles
  !> absolute 0.02 deg), a_S4y and group 4-5 forces relative 5e-3 (docs/sixbar.md, errata).
  subroutine test_example_printed(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rk = 2.0e-3_wp, ra = 0.02_wp, rf = 5.0e-3_wp
    type(sixbar_step_t) :: s
    type(sixbar_params_t) :: p
    s = sixbar_step(ref, phi_example * deg_to_rad, f5_example)
    call check_true(t, "example assembles", s%status == sixbar_ok, "status not ok")
    call check_close(t, "manual phi2 = 31.34 deg", 31.34_wp, s%pos%phi2 * rad_to_deg, 0.0_wp, ra)
    call check_close(t, "manual phi3 = 89.83 deg", 89.83_wp, s%pos%phi3 * rad_to_deg, 0.0_wp, ra)
    call check_close(t, "manual phi4 = 354.84 deg", 354.84_wp, modulo(s%pos%phi4 * rad_to_deg, 360.0_wp), 0.0_wp, ra)
    call check_close(t, "manual u21 = -0.11478", -0.11478_wp, s%pos%u21, rk, 0.0_wp)
    call check_close(t, "manual u31 = 0.22677", 0.22677_wp, s%pos%u31, rk, 0.0_wp)
    call check_close(t, "manual u41 = -0.15355", -0.15355_wp, s%pos%u41, rk, 0.0_wp)
    call check_close(t, "manual eps_q3 = 0.30750", 0.30750_wp, s%pos%eps_q3, rk, 0.0_wp)
    call check_close(t, "manual eps_q4 = -0.14116", -0.14116_wp, s%pos%eps_q4, rk, 0.0_wp)
    call check_close(t, "manual a_qH = -0.09657", -0.09657_wp, s%pos%a_hq(1), rk, 0.0_wp)
    call check_close(t, "manual eps3 = 3075 rad/s^2", 3075.0_wp, s%eps(3), rk, 0.0_wp)
    call check_close(t, "manual eps4 = -1412 rad/s^2", -1412.0_wp, s%eps(4), rk, 0.0_wp)
    call check_close(t, "manual a_H = -965.7 m/s^2", -965.7_wp, s%pos%a_hq(1) * ref%omega1**2, rk, 0.0_wp)
    call check_close(t, "manual a_S4x = -929.5 m/s^2 (frame 2)", -929.5_wp, s%pos%a_s4q(1) * ref%omega1**2, rk, 0.0_wp)
    call check_close(t, "manual a_S4y = 138 m/s^2 (frame 2)", 138.0_wp, s%pos%a_s4q(2) * ref%omega1**2, rf, 0.0_wp)
    call check_close(t, "manual M_54E = 122.58 N*m", 122.58_wp, s%m54e, rf, 0.0_wp)
    call check_close(t, "manual F56 = -615.4 N", -615.4_wp, s%f56, rf, 0.0_wp)
    call check_close(t, "manual F54x = -6854 N (frame 2)", -6854.0_wp, s%f54(1), rk, 0.0_wp)
    call check_close(t, "manual F54y = 615.4 N (frame 2)", 615.4_wp, s%f54(2), rf, 0.0_wp)
    call check_close(t, "manual eps_q2 ~ 0.2326 (correct)", 0.2326_wp, s%pos%eps_q2, rk, 0.0_wp)
    p = ref
    p%legacy_eq2 = .true.
    s = sixbar_step(p, phi_example * deg_to_rad, f5_example)
    call check_close(t, "manual eps_q2 = 0.201638 (legacy_eq2)", 0.201638_wp, s%pos%eps_q2, 5.0e-4_wp, 0.0_wp)
    ! group 2-3 of the manual (it inherits the erratum): F36 = (18548.77, 8935.10) N in frame 1,
    ! |F36| = 20588.7 N (the OCR'd text reads 18348.77; 18548.77 is what its |F36| and cos need)
    call check_close(t, "manual F36x = 18548.77 N (legacy_eq2)", 18548.77_wp, s%f36(1), rk, 0.0_wp)
    call check_close(t, "manual F36y = 8935.10 N (legacy_eq2)", 8935.10_wp, s%f36(2), rk, 0.0_wp)
    call check_close(t, "manual |F36| = 20588.7 N (legacy_eq2)", 20588.7_wp, hypot(s%f36(1), s%f36(2)), rk, 0.0_wp)
  end subroutine test_example_printed

  !> Exact values at the worked example, from an independent prototype (complex numbers,
  !> all reactions from one 14x14 linear system): relative 1e-9.
  subroutine test_example_exact(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: r = 1.0e-9_wp
    type(sixbar_step_t) :: s
    s = sixbar_step(ref, phi_example * deg_to_rad, f5_example)
    call check_close(t, "exact phi2, deg", 31.3465374179497_wp, s%pos%phi2 * rad_to_deg, r, 0.0_wp)
    call check_close(t, "exact phi3, deg", 89.8324542454639_wp, s%pos%phi3 * rad_to_deg, r, 0.0_wp)
    call check_close(t, "exact phi4, deg", 354.855180345847_wp, modulo(s%pos%phi4 * rad_to_deg, 360.0_wp), r, 0.0_wp)
    call check_close(t, "exact u21", -0.114735218908434_wp, s%pos%u21, r, 0.0_wp)
    call check_close(t, "exact u31", 0.226797085864697_wp, s%pos%u31, r, 0.0_wp)
    call check_close(t, "exact u41", -0.15364825698044_wp, s%pos%u41, r, 0.0_wp)
    call check_close(t, "exact eps_q2", 0.232693784335919_wp, s%pos%eps_q2, r, 0.0_wp)
    call check_close(t, "exact eps_q3", 0.307555545359926_wp, s%pos%eps_q3, r, 0.0_wp)
    call check_close(t, "exact eps_q4", -0.141297844642941_wp, s%pos%eps_q4, r, 0.0_wp)
    call check_close(t, "exact a_qH", -0.0965827828633182_wp, s%pos%a_hq(1), r, 0.0_wp)
    call check_close(t, "exact a_S4x", -929.644490841151_wp, s%pos%a_s4q(1) * ref%omega1**2, r, 0.0_wp)
    call check_close(t, "exact a_S4y", 138.611596080614_wp, s%pos%a_s4q(2) * ref%omega1**2, r, 0.0_wp)
    call check_close(t, "exact M_54E", 122.074115493108_wp, s%m54e, r, 0.0_wp)
    call check_close(t, "exact F56", -612.839571398742_wp, s%f56, r, 0.0_wp)
    call check_close(t, "exact F54x", -6854.96697179909_wp, s%f54(1), r, 0.0_wp)
    call check_close(t, "exact F54y", 612.839571398742_wp, s%f54(2), r, 0.0_wp)
    call check_close(t, "exact F36x", 18550.7492114616_wp, s%f36(1), r, 0.0_wp)
    call check_close(t, "exact F36y", 9130.88506919658_wp, s%f36(2), r, 0.0_wp)
    call check_close(t, "exact F16x", -13069.6954932293_wp, s%f16(1), r, 0.0_wp)
    call check_close(t, "exact F16y", -8416.02721474552_wp, s%f16(2), r, 0.0_wp)
    call check_close(t, "exact M1", 902.035489990192_wp, s%m1, r, 0.0_wp)
    call check_true(t, "example self-check residual <= 1e-12", s%residual <= 1.0e-12_wp, "residual too large")
    call check_true(t, "example self-check M1 power <= 1e-12", s%mismatch <= 1.0e-12_wp, "mismatch too large")
  end subroutine test_example_exact

  !> legacy_eq2 changes eps_q2 (and with it group 2-3 and the crank) but nothing of
  !> group 4-5; finite differences of u21 agree with the correct eps_q2, not the legacy one.
  subroutine test_erratum(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: h = 1.0e-4_wp
    type(sixbar_params_t) :: p
    type(sixbar_step_t) :: s0, s1
    type(sixbar_position_t) :: pm, pp
    real(wp) :: phi, fd
    phi = phi_example * deg_to_rad
    p = ref
    p%legacy_eq2 = .true.
    s0 = sixbar_step(ref, phi, f5_example)
    s1 = sixbar_step(p, phi, f5_example)
    call check_close(t, "legacy: same F56", s0%f56, s1%f56, 1.0e-15_wp, 0.0_wp)
    call check_close(t, "legacy: same F43x", s0%f43(1), s1%f43(1), 1.0e-15_wp, 0.0_wp)
    call check_close(t, "legacy: same eps_q3", s0%pos%eps_q3, s1%pos%eps_q3, 1.0e-15_wp, 0.0_wp)
    call check_true(t, "legacy: eps_q2 differs by > 10 %", abs(s1%pos%eps_q2 / s0%pos%eps_q2 - 1.0_wp) > 0.1_wp, &
                    "legacy switch has no effect")
    call check_true(t, "legacy: M1 differs", abs(s1%m1 - s0%m1) > 1.0_wp, "legacy switch does not reach M1")
    call check_true(t, "legacy: self-check still <= 1e-12", max(s1%residual, s1%mismatch) <= 1.0e-12_wp, &
                    "legacy self-check")
    pm = sixbar_position(ref, phi - h)
    pp = sixbar_position(ref, phi + h)
    fd = (pp%u21 - pm%u21) / (2 * h)
    call check_close(t, "d u21/d phi1 (FD) = eps_q2 correct", fd, s0%pos%eps_q2, 1.0e-7_wp, 0.0_wp)
    call check_true(t, "d u21/d phi1 (FD) != eps_q2 legacy", abs(fd - s1%pos%eps_q2) > 0.02_wp, &
                    "legacy value agrees with FD")
  end subroutine test_erratum

  !> Every transfer function against central differences of positions over a full turn.
  subroutine test_finite_differences(t)
    type(test_counts_t), intent(inout) :: t
    !> FD step, rad; truncation ~h^2 ~ 1e-8, roundoff of 2nd differences ~1e-16/h^2 ~ 1e-8.
    real(wp), parameter :: h = 1.0e-4_wp
    !> Tolerances: relative 1e-6, absolute 1e-7 (m/rad, m/rad^2 or rad/rad).
    real(wp), parameter :: rtol = 1.0e-6_wp, atol = 1.0e-7_wp
    type(sixbar_position_t) :: p0, pm, pp
    character(len=32) :: at
    real(wp) :: phi
    integer :: i, c
    do i = 0, 35
      phi = (real(i, wp) * 10.0_wp + 3.7_wp) * deg_to_rad
      write (at, '(" at phi1=",f7.2)') phi * rad_to_deg
      p0 = sixbar_position(ref, phi)
      pm = sixbar_position(ref, phi - h)
      pp = sixbar_position(ref, phi + h)
      call check_true(t, "assembles"//trim(at), p0%status == sixbar_ok .and. pm%status == sixbar_ok .and. &
                      pp%status == sixbar_ok, "status not ok")
      call check_close(t, "u21"//trim(at), d1(pp%phi2, pm%phi2), p0%u21, rtol, atol)
      call check_close(t, "u31"//trim(at), d1(pp%phi3, pm%phi3), p0%u31, rtol, atol)
      call check_close(t, "u41"//trim(at), d1(pp%phi4, pm%phi4), p0%u41, rtol, atol)
      call check_close(t, "eps_q2"//trim(at), d2(pp%phi2, p0%phi2, pm%phi2), p0%eps_q2, rtol, atol)
      call check_close(t, "eps_q3"//trim(at), d2(pp%phi3, p0%phi3, pm%phi3), p0%eps_q3, rtol, atol)
      call check_close(t, "eps_q4"//trim(at), d2(pp%phi4, p0%phi4, pm%phi4), p0%eps_q4, rtol, atol)
      do c = 1, 2
        call check_close(t, "v_s2q"//trim(at), (pp%s2(c) - pm%s2(c)) / (2 * h), p0%v_s2q(c), rtol, atol)
        call check_close(t, "a_s2q"//trim(at), (pp%s2(c) - 2 * p0%s2(c) + pm%s2(c)) / h**2, p0%a_s2q(c), rtol, atol)
        call check_close(t, "v_s4q"//trim(at), (pp%s4(c) - pm%s4(c)) / (2 * h), p0%v_s4q(c), rtol, atol)
        call check_close(t, "a_s4q"//trim(at), (pp%s4(c) - 2 * p0%s4(c) + pm%s4(c)) / h**2, p0%a_s4q(c), rtol, atol)
        call check_close(t, "v_hq"//trim(at), (pp%h(c) - pm%h(c)) / (2 * h), p0%v_hq(c), rtol, atol)
        call check_close(t, "a_hq"//trim(at), (pp%h(c) - 2 * p0%h(c) + pm%h(c)) / h**2, p0%a_hq(c), rtol, atol)
      end do
      call check_close(t, "H stays on the guide"//trim(at), ref%lam_e * ref%l1, p0%h(2), 1.0e-15_wp, 0.0_wp)
      call check_close(t, "v_H has no y2 component"//trim(at), 0.0_wp, p0%v_hq(2), 0.0_wp, 1.0e-16_wp)
      call check_close(t, "a_H has no y2 component"//trim(at), 0.0_wp, p0%a_hq(2), 0.0_wp, 1.0e-16_wp)
      call check_close(t, "|BC| = l2"//trim(at), ref%lam2 * ref%l1, hypot(p0%c(1) - p0%b(1), p0%c(2) - p0%b(2)), &
                       1.0e-13_wp, 0.0_wp)
      call check_close(t, "|EH| = l4"//trim(at), ref%lam4 * ref%l1, hypot(p0%h(1) - p0%e(1), p0%h(2) - p0%e(2)), &
                       1.0e-13_wp, 0.0_wp)
      call check_true(t, "C, D, E in line, D between"//trim(at), &
                      abs(cross(p0%c - p0%d, p0%e1 - p0%d)) < 1.0e-15_wp .and. &
                      dot_product(p0%c - p0%d, p0%e1 - p0%d) < 0.0_wp, "rocker not straight")
    end do
  contains
    !> Central first difference of an angle, wrapped across +-pi.
    pure real(wp) function d1(fp, fm)
      real(wp), intent(in) :: fp, fm
      d1 = wrap(fp - fm) / (2 * h)
    end function d1
    !> Central second difference of an angle, wrapped across +-pi.
    pure real(wp) function d2(fp, f0, fm)
      real(wp), intent(in) :: fp, f0, fm
      d2 = (wrap(fp - f0) - wrap(f0 - fm)) / h**2
    end function d2
  end subroutine test_finite_differences

  !> Component i of a plane vector (for expressions).
  pure real(wp) function comp(v, i)
    real(wp), intent(in) :: v(2)
    integer, intent(in) :: i
    comp = v(i)
  end function comp

  !> An angle difference wrapped into [-pi, pi), rad.
  pure real(wp) function wrap(x)
    real(wp), intent(in) :: x
    wrap = modulo(x + pi, 2 * pi) - pi
  end function wrap

  !> Every step of data/sixbar.nml (and its legacy_eq2 variant): residual and power <= 1e-9.
  subroutine test_reference_selfcheck(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: limit = 1.0e-9_wp
    type(sixbar_deck_t) :: deck
    type(sixbar_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    character(len=64) :: detail
    integer :: k, pass
    call load_deck("data/sixbar.nml", source, error)
    if (.not. allocated(error)) call read_sixbar_deck(source, deck, error)
    call check_true(t, "read data/sixbar.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    call check_true(t, "reference deck has 13 steps", deck%n == 13, "wrong step count")
    call check_close(t, "reference deck starts at angle B0AD = 36.77 deg", 36.77_wp, deck%phi_start, 0.0_wp, 0.005_wp)
    call check_close(t, "reference deck f5(7) = 1000", 1000.0_wp, deck%f5(7), 0.0_wp, 0.0_wp)
    call check_close(t, "reference deck f5(8) = 0", 0.0_wp, deck%f5(8), 0.0_wp, 0.0_wp)
    do pass = 1, 2
      if (pass == 2) deck%p%legacy_eq2 = .true.
      call sixbar_solve("data/sixbar.nml", deck, steps, error)
      call check_true(t, "reference deck assembles", .not. allocated(error), "geometry error")
      if (allocated(error)) return
      do k = 1, size(steps)
        write (detail, '("pass ",i0," step ",i0,": ",es10.3)') pass, k, steps(k)%residual
        call check_true(t, "sixbar equilibrium residual <= 1e-9", steps(k)%residual <= limit, trim(detail))
        write (detail, '("pass ",i0," step ",i0,": ",es10.3)') pass, k, steps(k)%mismatch
        call check_true(t, "sixbar M1 power balance <= 1e-9", steps(k)%mismatch <= limit, trim(detail))
      end do
    end do
  end subroutine test_reference_selfcheck

  !> One-degree sweep of the example data over a full turn: self-check <= 1e-9.
  subroutine test_sweep_selfcheck(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: limit = 1.0e-9_wp
    type(sixbar_step_t) :: s
    real(wp) :: worst_r, worst_m
    integer :: i
    worst_r = 0.0_wp
    worst_m = 0.0_wp
    do i = 0, 359
      s = sixbar_step(ref, real(i, wp) * deg_to_rad, f5_example)
      if (s%status /= sixbar_ok) then
        worst_r = huge(1.0_wp)
        exit
      end if
      worst_r = max(worst_r, s%residual)
      worst_m = max(worst_m, s%mismatch)
    end do
    call check_close(t, "sweep: max residual <= 1e-9", 0.0_wp, worst_r, 0.0_wp, limit)
    call check_close(t, "sweep: max M1 mismatch <= 1e-9", 0.0_wp, worst_m, 0.0_wp, limit)
  end subroutine test_sweep_selfcheck

  !> omega1 = 0, g = 0, only F5: link 4 is a two-force member, so F56 = F5*tan(phi4),
  !> F43 = -(F5/cos(phi4)) e4; link 2 too, so F21 is along BC; the frame takes -F5.
  subroutine test_slider_load_statics(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: f = 1000.0_wp, rtol = 1.0e-12_wp, atol = 1.0e-9_wp
    type(sixbar_params_t) :: p
    type(sixbar_step_t) :: s
    real(wp) :: frame(2)
    integer :: i
    p = ref
    p%omega1 = 0.0_wp
    p%g = 0.0_wp
    do i = 0, 3
      s = sixbar_step(p, (20.0_wp + 90.0_wp * i) * deg_to_rad, f)
      call check_close(t, "statics: F56 = F5 tan(phi4)", f * tan(s%pos%phi4), s%f56, rtol, atol)
      call check_close(t, "statics: F43x = -F5", -f, s%f43(1), rtol, atol)
      call check_close(t, "statics: F43y = -F5 tan(phi4)", -f * tan(s%pos%phi4), s%f43(2), rtol, atol)
      call check_close(t, "statics: F21 along BC", 0.0_wp, cross(unit_at(s%pos%phi2), s%f21), 0.0_wp, atol)
      call check_close(t, "statics: F16 = F21 (no weight)", s%f21(2), s%f16(2), rtol, atol)
      frame = s%f16 + s%f36 + sixbar_frame2_to_frame1(p, [0.0_wp, s%f56])
      call check_close(t, "statics: frame takes -F5 (x1)", comp(-sixbar_frame2_to_frame1(p, [f, 0.0_wp]), 1), &
                       frame(1), rtol, atol)
      call check_close(t, "statics: frame takes -F5 (y1)", comp(-sixbar_frame2_to_frame1(p, [f, 0.0_wp]), 2), &
                       frame(2), rtol, atol)
      call check_close(t, "statics: M1 = -F5 dx_H/dphi1", -f * s%pos%v_hq(1), s%m1, rtol, atol)
    end do
  end subroutine test_slider_load_statics

  !> omega1 = 0, no slider load: the frame reactions carry the whole weight, straight up
  !> in the global frame (gravity carried into frames 1 and 2 consistently).
  subroutine test_gravity_statics(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-12_wp, atol = 1.0e-9_wp
    type(sixbar_params_t) :: p
    type(sixbar_step_t) :: s
    real(wp) :: frame(2), weight
    integer :: i
    p = ref
    p%omega1 = 0.0_wp
    weight = (p%m1 + p%m2 + p%m3 + p%m4 + p%m5) * p%g
    do i = 0, 3
      s = sixbar_step(p, (20.0_wp + 90.0_wp * i) * deg_to_rad, 0.0_wp)
      frame = s%f16 + s%f36 + sixbar_frame2_to_frame1(p, [0.0_wp, s%f56])
      call check_close(t, "gravity: frame reaction = +weight (x1)", comp(-weight * sixbar_down1(p), 1), &
                       frame(1), rtol, atol)
      call check_close(t, "gravity: frame reaction = +weight (y1)", comp(-weight * sixbar_down1(p), 2), &
                       frame(2), rtol, atol)
    end do
  end subroutine test_gravity_statics

  !> The whole mechanism in frame 1 at full speed: frame reactions + every load = 0 and
  !> their moment about A + M1 = 0. Fails if F43 (or any frame-2 load) is carried wrongly.
  subroutine test_global_balance(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-11_wp
    type(sixbar_params_t) :: p
    type(sixbar_step_t) :: s
    type(sixbar_position_t) :: q
    real(wp) :: w2, d1(2), d2(2), sf(2), sm, scale, h1(2), s41(2), l4s(2), l5(2), l2s(2)
    integer :: i
    p = ref
    p%g = 9.81_wp
    w2 = p%omega1**2
    d1 = sixbar_down1(p)
    d2 = sixbar_down2(p)
    do i = 0, 5
      s = sixbar_step(p, (10.0_wp + 60.0_wp * i) * deg_to_rad, f5_example)
      q = s%pos
      h1 = q%d + sixbar_frame2_to_frame1(p, q%h)
      s41 = q%d + sixbar_frame2_to_frame1(p, q%s4)
      l2s = p%m2 * p%g * d1 - p%m2 * q%a_s2q * w2
      l4s = sixbar_frame2_to_frame1(p, p%m4 * p%g * d2 - p%m4 * q%a_s4q * w2)
      l5 = sixbar_frame2_to_frame1(p, p%m5 * p%g * d2 - p%m5 * [q%a_hq(1) * w2, 0.0_wp] + [f5_example, 0.0_wp])
      sf = s%f16 + s%f36 + sixbar_frame2_to_frame1(p, [0.0_wp, s%f56]) + (p%m1 + p%m3) * p%g * d1 + l2s + l4s + l5
      scale = hypot(s%f16(1), s%f16(2)) + hypot(s%f36(1), s%f36(2))
      call check_close(t, "global balance: forces (x1)", 0.0_wp, sf(1), 0.0_wp, rtol * scale)
      call check_close(t, "global balance: forces (y1)", 0.0_wp, sf(2), 0.0_wp, rtol * scale)
      sm = s%m1 + cross(q%d, s%f36) + cross(h1, sixbar_frame2_to_frame1(p, [0.0_wp, s%f56])) &
           + cross(q%d, p%m3 * p%g * d1) + cross(q%s2, l2s) + cross(s41, l4s) + cross(h1, l5) &
           - (p%j2 * q%eps_q2 + p%j3 * q%eps_q3 + p%j4 * q%eps_q4) * w2
      call check_close(t, "global balance: moments about A", 0.0_wp, sm, 0.0_wp, rtol * scale * 0.5_wp)
    end do
  end subroutine test_global_balance

  !> Frames: x2 points straight down (gravity along +x2), angles in frame 2 = frame 1 + 180 - beta.
  subroutine test_frames(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: tol = 1.0e-15_wp
    real(wp) :: v(2), beta
    call check_close(t, "gravity along +x2", 1.0_wp, comp(sixbar_down2(ref), 1), tol, 0.0_wp)
    call check_close(t, "gravity has no y2", 0.0_wp, comp(sixbar_down2(ref), 2), 0.0_wp, tol)
    beta = atan2(ref%a, ref%b)
    call check_close(t, "beta = 26.565 deg", 26.565_wp, beta * rad_to_deg, 0.0_wp, 1.0e-3_wp)
    v = sixbar_frame2_to_frame1(ref, unit_at(174.17_wp * deg_to_rad))
    call check_close(t, "angle 174.17 in frame 2 is 174.17-153.435 in frame 1", &
                     174.17_wp - 180.0_wp + beta * rad_to_deg, atan2(v(2), v(1)) * rad_to_deg, 1.0e-13_wp, 0.0_wp)
    v = sixbar_frame1_to_frame2(ref, sixbar_frame2_to_frame1(ref, [3.0_wp, -4.0_wp]))
    call check_close(t, "frame round trip x", 3.0_wp, v(1), tol * 10, 0.0_wp)
    call check_close(t, "frame round trip y", -4.0_wp, v(2), tol * 10, 0.0_wp)
  end subroutine test_frames

  !> Extreme position B0: crank and connecting rod in line, the rocker and the slider stop.
  subroutine test_extreme(t)
    type(test_counts_t), intent(inout) :: t
    type(sixbar_position_t) :: q
    real(wp) :: phi
    logical :: ok
    call sixbar_extreme_phi1(ref, phi, ok)
    call check_true(t, "extreme exists", ok, "no extreme position")
    call check_close(t, "angle B0AD = 36.77 deg", 36.77_wp, phi * rad_to_deg, 0.0_wp, 0.005_wp)
    q = sixbar_position(ref, phi)
    call check_close(t, "extreme: phi2 = phi1", 0.0_wp, wrap(q%phi2 - phi), 0.0_wp, 1.0e-12_wp)
    call check_close(t, "extreme: u31 = 0", 0.0_wp, q%u31, 0.0_wp, 1.0e-12_wp)
    call check_close(t, "extreme: slider stops", 0.0_wp, q%v_hq(1), 0.0_wp, 1.0e-12_wp)
  end subroutine test_extreme

  !> A step that cannot be assembled is reported with its number and angle (exit 3).
  subroutine test_assembly(t)
    type(test_counts_t), intent(inout) :: t
    type(sixbar_params_t) :: p
    type(sixbar_position_t) :: q
    type(sixbar_deck_t) :: deck
    type(sixbar_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    p = ref
    p%lam2 = 1.6_wp
    q = sixbar_position(p, 180.0_wp * deg_to_rad)
    call check_true(t, "short rod: contour 1 open at 180 deg", q%status == sixbar_open1, "status not open1")
    q = sixbar_position(p, 0.0_wp)
    call check_true(t, "short rod: assembles at 0 deg", q%status == sixbar_ok, "status not ok")
    p = ref
    p%lam_e = 5.5_wp
    q = sixbar_position(p, 60.0_wp * deg_to_rad)
    call check_true(t, "far guide: contour 2 open", q%status == sixbar_open2, "status not open2")
    call load_deck("data/sixbar.nml", source, error)
    if (.not. allocated(error)) call read_sixbar_deck(source, deck, error)
    if (allocated(error)) return
    deck%p%lam2 = 1.6_wp
    deck%phi_start = 0.0_wp
    deck%dphi = 30.0_wp
    call sixbar_solve("short.nml", deck, steps, error)
    call check_true(t, "short rod deck: geometry error", allocated(error), "no error")
    if (.not. allocated(error)) return
    call check_true(t, "short rod deck: exit 3", error%code == exit_geometry, "wrong exit code")
    call check_true(t, "short rod deck: names step 6 and its angle", &
                    index(error%message, "step 6 (phi1 = 150.") > 0, error%message)
  end subroutine test_assembly

end module test_sixbar
