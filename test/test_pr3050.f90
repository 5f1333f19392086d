!> PR 3050 tests: transfer functions against finite differences, self-check on the reference
!> deck, statics by hand (moments about C and A), constant and variable rocker speed against
!> an independent evaluation (numerical time derivatives + the 9 equations solved by LAPACK),
!> geometry errors, the step count.
module test_pr3050
  use kinetostat_kinds, only: wp, deg_to_rad, pi
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_vec2, only: unit_at, perp, cross
  use kinetostat_lapack, only: solve_dense
  use kinetostat_pr3050, only: pr3050_params_t, pr3050_position_t, pr3050_step_t, &
    pr3050_position, pr3050_check_position, pr3050_step
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck, pr3050_step_count
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_pr3050_layout, only: pr3050_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_pr3050_tests

  !> The spec's reference data (angles in rad).
  type(pr3050_params_t), parameter :: ref = pr3050_params_t(l_ca=1.667_wp, l_cb=1.222_wp, l_cs3=2.31_wp, &
    delta=10.5_wp * deg_to_rad, l_bs2=0.48_wp, l_s1a=0.42_wp, gamma=313.72_wp * deg_to_rad, g=9.81_wp, &
    m1=15.0_wp, m2=28.0_wp, m3=1056.0_wp, j1=1.5_wp, j2=1.5_wp, j3=622.0_wp)

  !> Positions of the independent evaluation (computed here from scratch, not by the product).
  type :: frame_t
    !> Pivot A, pin B, centres of mass S1, S2, S3, m.
    real(wp) :: a(2), b(2), s1(2), s2(2), s3(2)
    !> Unit vector B -> A.
    real(wp) :: e2(2)
    !> Axis angle B -> A, rad.
    real(wp) :: phi2
    !> Cylinder length |A - B|, m.
    real(wp) :: s
  end type frame_t

contains

  subroutine run_pr3050_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_finite_differences(t)
    call test_reference_selfcheck(t)
    call test_statics_by_hand(t)
    call test_statics_rocker_weight(t)
    call test_constant_speed(t)
    call test_variable_speed(t)
    call test_speed_scaling(t)
    call test_geometry_errors(t)
    call test_step_count(t)
  end subroutine run_pr3050_tests

  !> s', u23, eps23, s'' and the analogues of S1, S2, S3 against central differences in phi3.
  subroutine test_finite_differences(t)
    type(test_counts_t), intent(inout) :: t
    !> FD step, rad: truncation ~h^2 ~ 1e-8, roundoff of 2nd differences ~1e-16/h^2 ~ 1e-8.
    real(wp), parameter :: h = 1.0e-4_wp
    !> Tolerances: relative 1e-6, absolute 1e-7 (m/rad, rad/rad).
    real(wp), parameter :: rtol = 1.0e-6_wp, atol = 1.0e-7_wp
    real(wp), parameter :: angles_deg(*) = [43.72_wp, 61.0_wp, 88.72_wp, 10.0_wp, 120.0_wp, 200.0_wp, 300.0_wp, 350.0_wp]
    type(pr3050_position_t) :: p0, pm, pp
    character(len=32) :: at
    real(wp) :: phi2m, phi2p
    integer :: i, c
    do i = 1, size(angles_deg)
      write (at, '(" at phi3=",f7.2)') angles_deg(i)
      p0 = pr3050_position(ref, angles_deg(i) * deg_to_rad)
      pm = pr3050_position(ref, angles_deg(i) * deg_to_rad - h)
      pp = pr3050_position(ref, angles_deg(i) * deg_to_rad + h)
      phi2m = p0%phi2 + modulo(pm%phi2 - p0%phi2 + pi, 2 * pi) - pi
      phi2p = p0%phi2 + modulo(pp%phi2 - p0%phi2 + pi, 2 * pi) - pi
      call check_close(t, "s'"//trim(at), (pp%s - pm%s) / (2 * h), p0%ds, rtol, atol)
      call check_close(t, "s''"//trim(at), (pp%s - 2 * p0%s + pm%s) / h**2, p0%dds, rtol, atol)
      call check_close(t, "u23"//trim(at), (phi2p - phi2m) / (2 * h), p0%u23, rtol, atol)
      call check_close(t, "eps23"//trim(at), (phi2p - 2 * p0%phi2 + phi2m) / h**2, p0%eps23, rtol, atol)
      do c = 1, 2
        call check_close(t, "v_s1q"//trim(at), (pp%s1(c) - pm%s1(c)) / (2 * h), p0%v_s1q(c), rtol, atol)
        call check_close(t, "a_s1q"//trim(at), (pp%s1(c) - 2 * p0%s1(c) + pm%s1(c)) / h**2, p0%a_s1q(c), rtol, atol)
        call check_close(t, "v_s2q"//trim(at), (pp%s2(c) - pm%s2(c)) / (2 * h), p0%v_s2q(c), rtol, atol)
        call check_close(t, "a_s2q"//trim(at), (pp%s2(c) - 2 * p0%s2(c) + pm%s2(c)) / h**2, p0%a_s2q(c), rtol, atol)
        call check_close(t, "v_s3q"//trim(at), (pp%s3(c) - pm%s3(c)) / (2 * h), p0%v_s3q(c), rtol, atol)
        call check_close(t, "a_s3q"//trim(at), (pp%s3(c) - 2 * p0%s3(c) + pm%s3(c)) / h**2, p0%a_s3q(c), rtol, atol)
      end do
      ! the contour closes: B + s*e2 = A
      call check_close(t, "contour closes (x)"//trim(at), p0%a(1), p0%b(1) + p0%s * p0%e2(1), 1.0e-15_wp, 1.0e-14_wp)
      call check_close(t, "contour closes (y)"//trim(at), p0%a(2), p0%b(2) + p0%s * p0%e2(2), 1.0e-15_wp, 1.0e-14_wp)
    end do
  end subroutine test_finite_differences

  !> Every step of data/pr3050.nml: equilibrium residuals and power balance <= 1e-9.
  subroutine test_reference_selfcheck(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: limit = 1.0e-9_wp
    type(pr3050_deck_t) :: deck
    type(pr3050_step_t), allocatable :: steps(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    character(len=64) :: detail
    integer :: k
    call load_deck("data/pr3050.nml", source, error)
    if (.not. allocated(error)) call read_pr3050_deck(source, deck, error)
    call check_true(t, "read data/pr3050.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    call check_true(t, "pr3050 reference deck has 10 steps", deck%n == 10, "wrong step count")
    call pr3050_solve(deck, steps, error)
    call check_true(t, "pr3050 reference deck solves", .not. allocated(error), "geometry error")
    if (allocated(error)) return
    do k = 1, size(steps)
      write (detail, '("step ",i0,": ",es10.3)') k, steps(k)%residual
      call check_true(t, "pr3050 equilibrium residual <= 1e-9", steps(k)%residual <= limit, trim(detail))
      write (detail, '("step ",i0,": ",es10.3)') k, steps(k)%mismatch
      call check_true(t, "pr3050 F2 power balance <= 1e-9", steps(k)%mismatch <= limit, trim(detail))
      call check_close(t, "pr3050 F2 vs power balance", steps(k)%f2_power, steps(k)%f2, limit, limit)
    end do
    ! the trapezoidal law's end steps have omega3 = 0: the balance holds with analogues there too
    call check_close(t, "pr3050 step 1 has omega3 = 0", 0.0_wp, steps(1)%omega3, 0.0_wp, 0.0_wp)
    call check_close(t, "pr3050 step 10 has omega3 = 0", 0.0_wp, steps(10)%omega3, 0.0_wp, 0.0_wp)
  end subroutine test_reference_selfcheck

  !> omega3 = eps3 = 0, gravity along -y (gamma = 270), g = 10, a 3-4-5 triangle:
  !> C = (0,0), A = (4,0), B = (0,3) at phi3 = 90 deg, s = 5, e2 = (0.8,-0.6), n2 = (0.6,0.8).
  !> S1 = A - 2*e2 = (2.4,1.2), S2 = B + 2*e2 = (1.6,1.8), S3 = 2*(cos 0, sin 0) = (2,0) (delta = -90).
  !> G1 = (0,-100), G2 = (0,-50), G3 = (0,-1000).
  !> Links 1+2 about A: 160 + 120 + cross((-4,3), F23) = 0 -> cross((-4,3), F32) = 280.
  !> Link 3 about C:  cross((0,3), F32) + cross((2,0), G3) = -3*F32x - 2000 = 0 -> F32x = -2000/3;
  !> then -4*F32y - 3*F32x = 280 -> F32y = 430. F34 = -(F32 + G3) = (2000/3, 570).
  !> F14 = -(G1 + G2 + G3 + F34) = (-2000/3, 580). F2 = e2.(G2 - F32) = 533.33 + 288 = 2464/3.
  !> N21 = -n2.(G2 - F32) = -(400 - 384) = -16. M21 = -cross(S2 - B, G2) = 80.
  subroutine test_statics_by_hand(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-13_wp, atol = 1.0e-10_wp
    type(pr3050_params_t) :: p
    type(pr3050_step_t) :: s
    p = pr3050_params_t(l_ca=4.0_wp, l_cb=3.0_wp, l_cs3=2.0_wp, delta=-90.0_wp * deg_to_rad, l_bs2=2.0_wp, &
      l_s1a=2.0_wp, gamma=270.0_wp * deg_to_rad, g=10.0_wp, m1=10.0_wp, m2=5.0_wp, m3=100.0_wp, &
      j1=7.0_wp, j2=8.0_wp, j3=9.0_wp)
    s = pr3050_step(p, 90.0_wp * deg_to_rad, 0.0_wp, 0.0_wp)
    call check_close(t, "statics 3-4-5: F32x", -2000.0_wp / 3.0_wp, s%f32(1), rtol, atol)
    call check_close(t, "statics 3-4-5: F32y", 430.0_wp, s%f32(2), rtol, atol)
    call check_close(t, "statics 3-4-5: F34x", 2000.0_wp / 3.0_wp, s%f34(1), rtol, atol)
    call check_close(t, "statics 3-4-5: F34y", 570.0_wp, s%f34(2), rtol, atol)
    call check_close(t, "statics 3-4-5: F14x", -2000.0_wp / 3.0_wp, s%f14(1), rtol, atol)
    call check_close(t, "statics 3-4-5: F14y", 580.0_wp, s%f14(2), rtol, atol)
    call check_close(t, "statics 3-4-5: F2 (pushes the rod out)", 2464.0_wp / 3.0_wp, s%f2, rtol, atol)
    call check_close(t, "statics 3-4-5: N21", -16.0_wp, s%n21, rtol, atol)
    call check_close(t, "statics 3-4-5: M21", 80.0_wp, s%m21, rtol, atol)
    call check_close(t, "statics 3-4-5: s", 5.0_wp, s%s, rtol, atol)
    call check_close(t, "statics 3-4-5: residual", 0.0_wp, s%residual, 0.0_wp, 1.0e-14_wp)
    call check_close(t, "statics 3-4-5: F2 power balance", s%f2, s%f2_power, rtol, atol)
  end subroutine test_statics_by_hand

  !> omega3 = eps3 = 0, only the rocker has weight (reference geometry, every step of the range):
  !> the cylinder-rod assembly is then a two-force member along AB, and moments of the rocker
  !> about C give F2*h = -M_C(G3), h = l_CA*l_CB*sin(phi3)/s the distance from C to the axis:
  !> cross(B, F32) + cross(S3, G3) = 0 with F32 = -F2*e2 and cross(B, e2) = -h.
  subroutine test_statics_rocker_weight(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-12_wp
    type(pr3050_params_t) :: p
    type(pr3050_step_t) :: s
    real(wp) :: phi3, b(2), s3(2), g3(2), len_ab, h, f2, weight
    character(len=32) :: at
    integer :: k
    p = ref
    p%m1 = 0.0_wp
    p%m2 = 0.0_wp
    weight = p%m3 * p%g
    do k = 0, 9
      phi3 = (43.72_wp + 5.0_wp * k) * deg_to_rad
      write (at, '(" at phi3=",f6.2)') phi3 / deg_to_rad
      s = pr3050_step(p, phi3, 0.0_wp, 0.0_wp)
      b = p%l_cb * [cos(phi3), sin(phi3)]
      len_ab = sqrt((p%l_ca - b(1))**2 + b(2)**2)
      h = p%l_ca * p%l_cb * sin(phi3) / len_ab
      s3 = p%l_cs3 * [cos(phi3 + p%delta), sin(phi3 + p%delta)]
      g3 = weight * [cos(p%gamma), sin(p%gamma)]
      f2 = -(s3(1) * g3(2) - s3(2) * g3(1)) / h
      call check_close(t, "rocker weight: F2*h = -M_C(G3)"//trim(at), f2, s%f2, rtol, 1.0e-9_wp)
      call check_close(t, "rocker weight: F14 = F2 along AB, |F14|"//trim(at), abs(f2), hypot(s%f14(1), s%f14(2)), &
                       rtol, 1.0e-9_wp)
      call check_close(t, "rocker weight: N21 = 0"//trim(at), 0.0_wp, s%n21, 0.0_wp, 1.0e-9_wp)
      call check_close(t, "rocker weight: M21 = 0"//trim(at), 0.0_wp, s%m21, 0.0_wp, 1.0e-9_wp)
      call check_close(t, "rocker weight: frame carries G3 (x)"//trim(at), -g3(1), s%f14(1) + s%f34(1), rtol, 1.0e-9_wp)
      call check_close(t, "rocker weight: frame carries G3 (y)"//trim(at), -g3(2), s%f14(2) + s%f34(2), rtol, 1.0e-9_wp)
    end do
  end subroutine test_statics_rocker_weight

  !> Constant rocker speed (eps3 = 0), the PR 3207-style analysis (a = a_q*omega^2): every
  !> reaction equals the independent evaluation.
  subroutine test_constant_speed(t)
    type(test_counts_t), intent(inout) :: t
    integer :: k
    do k = 0, 9
      call compare_independent(t, "omega3 = 0.5 const", ref, (43.72_wp + 5.0_wp * k) * deg_to_rad, 0.5_wp, 0.0_wp)
    end do
    call compare_independent(t, "omega3 = -2 const", ref, 150.0_wp * deg_to_rad, -2.0_wp, 0.0_wp)
    call compare_independent(t, "omega3 = 3 const", ref, 250.0_wp * deg_to_rad, 3.0_wp, 0.0_wp)
  end subroutine test_constant_speed

  !> Variable speed: the reference deck's (omega3, eps3) pairs, and a few more.
  subroutine test_variable_speed(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: omega3(*) = [0.0_wp, 0.28868_wp, 0.40825_wp, 0.5_wp, 0.5_wp, 0.5_wp, 0.5_wp, &
                                        0.40825_wp, 0.28868_wp, 0.0_wp]
    real(wp), parameter :: eps3(*) = [0.47746_wp, 0.47746_wp, 0.47746_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                                      -0.47746_wp, -0.47746_wp, -0.47746_wp]
    integer :: k
    do k = 1, 10
      call compare_independent(t, "reference speed law", ref, (43.72_wp + 5.0_wp * (k - 1)) * deg_to_rad, &
                               omega3(k), eps3(k))
    end do
    call compare_independent(t, "omega3 = 1.5, eps3 = -4", ref, 300.0_wp * deg_to_rad, 1.5_wp, -4.0_wp)
    call compare_independent(t, "omega3 = 0, eps3 = 2", ref, 20.0_wp * deg_to_rad, 0.0_wp, 2.0_wp)
  end subroutine test_variable_speed

  !> With g = 0 and eps3 = 0 every force is proportional to omega3^2.
  subroutine test_speed_scaling(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: rtol = 1.0e-12_wp, atol = 1.0e-9_wp
    type(pr3050_params_t) :: p
    type(pr3050_step_t) :: s1, s2
    p = ref
    p%g = 0.0_wp
    s1 = pr3050_step(p, 60.0_wp * deg_to_rad, 0.5_wp, 0.0_wp)
    s2 = pr3050_step(p, 60.0_wp * deg_to_rad, 1.0_wp, 0.0_wp)
    call check_close(t, "omega^2 scaling: F2", 4.0_wp * s1%f2, s2%f2, rtol, atol)
    call check_close(t, "omega^2 scaling: F34x", 4.0_wp * s1%f34(1), s2%f34(1), rtol, atol)
    call check_close(t, "omega^2 scaling: F14y", 4.0_wp * s1%f14(2), s2%f14(2), rtol, atol)
    call check_close(t, "omega^2 scaling: M21", 4.0_wp * s1%m21, s2%m21, rtol, atol)
  end subroutine test_speed_scaling

  !> s = 0 (B on A) and the dead position (axis through C) are geometry errors; 90 deg is fine.
  subroutine test_geometry_errors(t)
    type(test_counts_t), intent(inout) :: t
    type(pr3050_params_t) :: p
    type(error_t), allocatable :: error
    call pr3050_check_position(ref, 90.0_wp * deg_to_rad, error)
    call check_true(t, "geometry ok at 90 deg", .not. allocated(error), "unexpected error")
    call pr3050_check_position(ref, 180.0_wp * deg_to_rad, error)
    call check_true(t, "dead position at 180 deg", allocated(error), "no error")
    if (allocated(error)) call check_true(t, "dead position -> exit 3", error%code == exit_geometry, "wrong code")
    call pr3050_check_position(ref, 0.0_wp, error)
    call check_true(t, "dead position at 0 deg", allocated(error), "no error")
    p = ref
    p%l_cb = p%l_ca
    call pr3050_check_position(p, 0.0_wp, error)
    call check_true(t, "s = 0 when l_cb = l_ca at 0 deg", allocated(error), "no error")
    if (allocated(error)) call check_true(t, "s = 0 message", index(error%message, "s = 0") > 0, error%message)
    call pr3050_check_position(p, 360.0_wp * deg_to_rad, error)
    call check_true(t, "s = 0 when l_cb = l_ca at 360 deg", allocated(error), "no error")
    call pr3050_check_position(p, 1.0_wp * deg_to_rad, error)
    call check_true(t, "l_cb = l_ca fine at 1 deg", .not. allocated(error), "unexpected error")
  end subroutine test_geometry_errors

  !> N = (phi3_end - phi3_start)/dphi3 + 1, whole numbers only.
  subroutine test_step_count(t)
    type(test_counts_t), intent(inout) :: t
    call check_true(t, "steps 43.72..88.72 by 5 = 10", pr3050_step_count(43.72_wp, 88.72_wp, 5.0_wp) == 10, "not 10")
    call check_true(t, "steps 0.1..0.7 by 0.1 = 7", pr3050_step_count(0.1_wp, 0.7_wp, 0.1_wp) == 7, "not 7")
    call check_true(t, "steps 0..10 by 3 not whole", pr3050_step_count(0.0_wp, 10.0_wp, 3.0_wp) == 0, "not 0")
    call check_true(t, "steps 0..10 by 1e-9 too many", pr3050_step_count(0.0_wp, 10.0_wp, 1.0e-9_wp) == -1, "not -1")
  end subroutine test_step_count

  ! ---------------------------------------------------------------------------------------
  ! Independent evaluation: positions from scratch, velocities and accelerations by central
  ! differences in time of phi3(t) = phi3 + omega3*t + eps3*t^2/2, and the nine equilibrium
  ! equations of links 1, 2, 3 assembled as one linear system solved by LAPACK.
  ! Unknowns x = [F14x, F14y, F34x, F34y, F32x, F32y, N21, M21, F2].

  !> Positions at rocker angle `phi3` (rad), written without the product's code.
  pure function frame_at(p, phi3) result(f)
    type(pr3050_params_t), intent(in) :: p
    real(wp), intent(in) :: phi3
    type(frame_t) :: f
    f%a = [p%l_ca, 0.0_wp]
    f%b = p%l_cb * [cos(phi3), sin(phi3)]
    f%s = sqrt(sum((f%a - f%b)**2))
    f%e2 = (f%a - f%b) / f%s
    f%phi2 = atan2(f%e2(2), f%e2(1))
    f%s1 = f%a - p%l_s1a * f%e2
    f%s2 = f%b + p%l_bs2 * f%e2
    f%s3 = p%l_cs3 * [cos(phi3 + p%delta), sin(phi3 + p%delta)]
  end function frame_at

  subroutine independent_step(p, phi3, omega3, eps3, x, power)
    type(pr3050_params_t), intent(in) :: p
    real(wp), intent(in) :: phi3, omega3, eps3
    !> The nine unknowns.
    real(wp), intent(out) :: x(9)
    !> Residual of the power balance F2*ds/dt + sum L.v + sum M*omega, W.
    real(wp), intent(out) :: power
    type(frame_t) :: fm, f0, fp
    type(error_t), allocatable :: error
    real(wp) :: h, acc(2, 3), vel(2, 3), l(2, 3), mphi(3), eps2, omega2, phi2m, phi2p, down(2), n2(2)
    real(wp) :: m(9, 9), rhs(9), mass(3), s_dot
    ! time step giving a rocker turn of ~2e-4 rad (or a time of 1e-3 s at rest)
    h = 2.0e-4_wp / max(abs(omega3), sqrt(abs(eps3)), 0.2_wp)
    fm = frame_at(p, phi3 - omega3 * h + eps3 * h**2 / 2)
    f0 = frame_at(p, phi3)
    fp = frame_at(p, phi3 + omega3 * h + eps3 * h**2 / 2)
    acc(:, 1) = (fp%s1 - 2 * f0%s1 + fm%s1) / h**2
    acc(:, 2) = (fp%s2 - 2 * f0%s2 + fm%s2) / h**2
    acc(:, 3) = (fp%s3 - 2 * f0%s3 + fm%s3) / h**2
    vel(:, 1) = (fp%s1 - fm%s1) / (2 * h)
    vel(:, 2) = (fp%s2 - fm%s2) / (2 * h)
    vel(:, 3) = (fp%s3 - fm%s3) / (2 * h)
    phi2m = f0%phi2 + modulo(fm%phi2 - f0%phi2 + pi, 2 * pi) - pi
    phi2p = f0%phi2 + modulo(fp%phi2 - f0%phi2 + pi, 2 * pi) - pi
    eps2 = (phi2p - 2 * f0%phi2 + phi2m) / h**2
    omega2 = (phi2p - phi2m) / (2 * h)
    s_dot = (fp%s - fm%s) / (2 * h)
    mass = [p%m1, p%m2, p%m3]
    down = [cos(p%gamma), sin(p%gamma)]
    l(:, 1) = mass(1) * (p%g * down - acc(:, 1))
    l(:, 2) = mass(2) * (p%g * down - acc(:, 2))
    l(:, 3) = mass(3) * (p%g * down - acc(:, 3))
    mphi = -[p%j1 * eps2, p%j2 * eps2, p%j3 * eps3]
    n2 = [-f0%e2(2), f0%e2(1)]
    m = 0.0_wp
    ! link 1 (moments about A): F14 at A, -N21*n2 at B, couple -M21, oil F2*e2 on the axis, L1
    m(1, :) = [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, -n2(1), 0.0_wp, f0%e2(1)]
    m(2, :) = [0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, -n2(2), 0.0_wp, f0%e2(2)]
    m(3, 7) = -cross(f0%b - f0%a, n2)
    m(3, 8) = -1.0_wp
    rhs(1:2) = -l(:, 1)
    rhs(3) = -(cross(f0%s1 - f0%a, l(:, 1)) + mphi(1))
    ! link 2 (moments about B): -F32 at B, N21*n2 at B, couple M21, oil -F2*e2 on the axis, L2
    m(4, :) = [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, -1.0_wp, 0.0_wp, n2(1), 0.0_wp, -f0%e2(1)]
    m(5, :) = [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, -1.0_wp, n2(2), 0.0_wp, -f0%e2(2)]
    m(6, 8) = 1.0_wp
    rhs(4:5) = -l(:, 2)
    rhs(6) = -(cross(f0%s2 - f0%b, l(:, 2)) + mphi(2))
    ! link 3 (moments about C): F34 at C, F32 at B, L3
    m(7, :) = [0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
    m(8, :) = [0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
    m(9, 5) = -f0%b(2)
    m(9, 6) = f0%b(1)
    rhs(7:8) = -l(:, 3)
    rhs(9) = -(cross(f0%s3, l(:, 3)) + mphi(3))
    call solve_dense(m, rhs, x, error)
    if (allocated(error)) x = huge(1.0_wp)
    power = x(9) * s_dot + sum(l * vel) + (mphi(1) + mphi(2)) * omega2 + mphi(3) * omega3
  end subroutine independent_step

  !> The product's step against the independent evaluation, relative to the largest force.
  !> FD accelerations carry ~1e-8 relative error (truncation h^2, roundoff 1e-16/h^2), the
  !> inertia loads are a fraction of the forces: tolerance 1e-7 of the force scale (measured
  !> worst 1.1e-8 at omega3 = 1.5, eps3 = -4; dropping the v_q*eps3 term errs by ~5e-2).
  subroutine compare_independent(t, name, p, phi3, omega3, eps3)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name
    type(pr3050_params_t), intent(in) :: p
    real(wp), intent(in) :: phi3, omega3, eps3
    real(wp), parameter :: rel = 1.0e-7_wp
    type(pr3050_step_t) :: s
    real(wp) :: x(9), got(9), scale, power
    character(len=80) :: label
    integer :: i
    character(len=4), parameter :: names(9) = [character(len=4) :: "F14x", "F14y", "F34x", "F34y", &
                                               "F32x", "F32y", "N21", "M21", "F2"]
    s = pr3050_step(p, phi3, omega3, eps3)
    call independent_step(p, phi3, omega3, eps3, x, power)
    got = [s%f14, s%f34, s%f32, s%n21, s%m21, s%f2]
    scale = maxval(abs(x))
    write (label, '(a," phi3=",f7.2,": ")') name, phi3 / deg_to_rad
    do i = 1, 9
      call check_close(t, trim(label)//" "//trim(names(i))//" vs independent", x(i), got(i), 0.0_wp, rel * scale)
    end do
    ! the independent solution satisfies the power balance too (time derivatives, not analogues)
    call check_close(t, trim(label)//" independent power balance", 0.0_wp, power, 0.0_wp, &
                     rel * scale * (p%l_ca + p%l_cb + p%l_cs3) * max(abs(omega3), 1.0_wp))
  end subroutine compare_independent

end module test_pr3050
