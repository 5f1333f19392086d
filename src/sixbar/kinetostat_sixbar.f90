!> T.FTN: six-bar crank-rocker-slider mechanism of manual section 2.
!> Links: 1 crank AB (pivot A), 2 connecting rod BC, 3 rocker C-D-E pivoted at D (C and E on
!> opposite sides of D on one line), 4 connecting rod EH, 5 slider at H, 6 frame.
!> Frames: global x0 A y0 (y0 up, gravity -y0); frame 1: origin A, x1 along AD;
!> frame 2: origin D, an angle in frame 2 = the angle in frame 1 + (180 deg - beta),
!> beta = atan2(a, b), so x2 points straight down and the slider moves along x2 at y2 = e.
!> Contour A-B-C-D in frame 1, contour D-E-H in frame 2, kinematics by transfer functions;
!> group 4-5 (frame 2), group 2-3 (frame 1, F43 carried from frame 2), crank with M1;
!> self-check by per-link equilibrium residuals and the virtual-work value of M1.
module kinetostat_sixbar
  use kinetostat_kinds, only: wp, pi
  use kinetostat_vec2, only: unit_at, perp, cross
  use kinetostat_loads, only: inertia_force, inertia_moment, gravity_force
  use kinetostat_selfcheck, only: link_balance_t, link_balance, equilibrium_residual, power_mismatch, &
    load_moment_scale
  implicit none
  private
  public :: sixbar_params_t, sixbar_position_t, sixbar_step_t
  public :: sixbar_position, sixbar_step, sixbar_extreme_phi1, sixbar_reduced, sixbar_reduced_at
  public :: sixbar_accel, sixbar_frame2_to_frame1, sixbar_frame1_to_frame2, sixbar_down1, sixbar_down2
  public :: sixbar_ok, sixbar_open1, sixbar_dead1, sixbar_open2, sixbar_dead2, sixbar_dead_tol

  !> Status: the mechanism is assembled and regular.
  integer, parameter :: sixbar_ok = 0
  !> Status: contour A-B-C-D cannot close (|BD| outside [|l2 - l3|, l2 + l3]).
  integer, parameter :: sixbar_open1 = 1
  !> Status: dead position of contour A-B-C-D (B, C, D in line).
  integer, parameter :: sixbar_dead1 = 2
  !> Status: contour D-E-H cannot close (|e - y_E| > l4).
  integer, parameter :: sixbar_open2 = 3
  !> Status: dead position of contour D-E-H (link 4 perpendicular to the guide).
  integer, parameter :: sixbar_dead2 = 4
  !> |sin(phi3 - phi2)| or cos(phi4) below this is a dead (singular) position, dimensionless.
  real(wp), parameter :: sixbar_dead_tol = 1.0e-8_wp

  !> Mechanism data (SI units; ratios as in the manual).
  type :: sixbar_params_t
    !> x0 of the rocker pivot D (global frame, from A), m.
    real(wp) :: a = 0.0_wp
    !> y0 of the rocker pivot D (global frame, from A, up), m.
    real(wp) :: b = 0.0_wp
    !> Crank length AB, m.
    real(wp) :: l1 = 0.0_wp
    !> lambda2 = l_BC / l1, dimensionless.
    real(wp) :: lam2 = 0.0_wp
    !> lambda_S2 = l_BS2 / l_BC, dimensionless.
    real(wp) :: lam_s2 = 0.0_wp
    !> lambda3 = l_DC / l1, dimensionless.
    real(wp) :: lam3 = 0.0_wp
    !> lambda_DE = l_DE / l1, dimensionless.
    real(wp) :: lam_de = 0.0_wp
    !> lambda4 = l_EH / l1, dimensionless.
    real(wp) :: lam4 = 0.0_wp
    !> lambda_S4 = l_ES4 / l_EH, dimensionless.
    real(wp) :: lam_s4 = 0.0_wp
    !> lambda_e = e / l1 (slider guide at y2 = e), dimensionless, signed.
    real(wp) :: lam_e = 0.0_wp
    !> Mass of the crank (centre of mass at A), kg.
    real(wp) :: m1 = 0.0_wp
    !> Mass of the connecting rod BC, kg.
    real(wp) :: m2 = 0.0_wp
    !> Mass of the rocker (centre of mass at D), kg.
    real(wp) :: m3 = 0.0_wp
    !> Mass of the connecting rod EH, kg.
    real(wp) :: m4 = 0.0_wp
    !> Mass of the slider (centre of mass at H), kg.
    real(wp) :: m5 = 0.0_wp
    !> Reduced moment of inertia of the crank about A, kg*m^2 (no effect: eps1 = 0).
    real(wp) :: j1 = 0.0_wp
    !> Moment of inertia of link 2 about S2, kg*m^2.
    real(wp) :: j2 = 0.0_wp
    !> Moment of inertia of the rocker about D, kg*m^2.
    real(wp) :: j3 = 0.0_wp
    !> Moment of inertia of link 4 about S4, kg*m^2.
    real(wp) :: j4 = 0.0_wp
    !> Crank speed (constant), rad/s, counter-clockwise in frame 1 positive.
    real(wp) :: omega1 = 0.0_wp
    !> Gravity, m/s^2 (along -y0).
    real(wp) :: g = 0.0_wp
    !> Reproduce the manual's erratum: cos(phi1 - phi2) in the eps_q2 numerator.
    logical :: legacy_eq2 = .false.
  end type sixbar_params_t

  !> Positions and transfer functions (analogues, d/dphi1) at one crank angle.
  !> Points B, C, D, S2 and their analogues in frame 1; E, H, S4 and theirs in frame 2.
  type :: sixbar_position_t
    !> `sixbar_ok` or the reason the position does not exist / is singular.
    integer :: status = sixbar_ok
    !> Diagnostic of a failure: |BD| (m) for open1, sin(phi3 - phi2) for dead1,
    !> |e - y_E| (m) for open2, cos(phi4) for dead2.
    real(wp) :: detail = 0.0_wp
    !> Crank angle (frame 1), rad.
    real(wp) :: phi1 = 0.0_wp
    !> Angle of BC (frame 1), rad.
    real(wp) :: phi2 = 0.0_wp
    !> Angle of DC (frame 1), rad; DE is at phi3 - beta in frame 2.
    real(wp) :: phi3 = 0.0_wp
    !> Angle of EH (frame 2), rad, in (-pi/2, pi/2).
    real(wp) :: phi4 = 0.0_wp
    !> u21 = d phi2 / d phi1.
    real(wp) :: u21 = 0.0_wp
    !> u31 = d phi3 / d phi1.
    real(wp) :: u31 = 0.0_wp
    !> u41 = d phi4 / d phi1.
    real(wp) :: u41 = 0.0_wp
    !> eps_q2 = d u21 / d phi1 (or the manual's erroneous value when legacy_eq2).
    real(wp) :: eps_q2 = 0.0_wp
    !> eps_q3 = d u31 / d phi1.
    real(wp) :: eps_q3 = 0.0_wp
    !> eps_q4 = d u41 / d phi1.
    real(wp) :: eps_q4 = 0.0_wp
    !> Crank pin B (frame 1), m.
    real(wp) :: b(2) = 0.0_wp
    !> Joint C (frame 1), m.
    real(wp) :: c(2) = 0.0_wp
    !> Rocker pivot D (frame 1), m.
    real(wp) :: d(2) = 0.0_wp
    !> Joint E (frame 1), m.
    real(wp) :: e1(2) = 0.0_wp
    !> Centre of mass S2 (frame 1), m.
    real(wp) :: s2(2) = 0.0_wp
    !> Velocity analogue of S2 (frame 1), m/rad.
    real(wp) :: v_s2q(2) = 0.0_wp
    !> Acceleration analogue of S2 (frame 1), m/rad^2.
    real(wp) :: a_s2q(2) = 0.0_wp
    !> Joint E (frame 2), m.
    real(wp) :: e(2) = 0.0_wp
    !> Slider joint H (frame 2), m; h(2) = e.
    real(wp) :: h(2) = 0.0_wp
    !> Centre of mass S4 (frame 2), m.
    real(wp) :: s4(2) = 0.0_wp
    !> Velocity analogue of S4 (frame 2), m/rad.
    real(wp) :: v_s4q(2) = 0.0_wp
    !> Acceleration analogue of S4 (frame 2), m/rad^2.
    real(wp) :: a_s4q(2) = 0.0_wp
    !> Velocity analogue of H (frame 2), m/rad (y component 0).
    real(wp) :: v_hq(2) = 0.0_wp
    !> Acceleration analogue of H (frame 2), m/rad^2 (y component 0); a_qH = a_hq(1).
    real(wp) :: a_hq(2) = 0.0_wp
  end type sixbar_position_t

  !> Results of one crank step. Forces F_ij act on link i from link j.
  type :: sixbar_step_t
    !> `sixbar_ok` or the position failure (then nothing else is set).
    integer :: status = sixbar_ok
    !> Positions and transfer functions.
    type(sixbar_position_t) :: pos
    !> Slider load, N, signed along +x2.
    real(wp) :: f5 = 0.0_wp
    !> Angular accelerations of links 2, 3, 4, rad/s^2.
    real(wp) :: eps(2:4) = 0.0_wp
    !> Crank speed of the step, rad/s.
    real(wp) :: omega1 = 0.0_wp
    !> Crank acceleration of the step, rad/s^2 (0 at constant speed).
    real(wp) :: eps1 = 0.0_wp
    !> Moment about E of all loads on links 4 and 5 except the pair forces (frame 2), N*m.
    real(wp) :: m54e = 0.0_wp
    !> Guide on slider: signed y2 component, N.
    real(wp) :: f56 = 0.0_wp
    !> Link 4 on slider at H (frame 2), N.
    real(wp) :: f54(2) = 0.0_wp
    !> Slider on link 4 at H (frame 2), N (= -f54).
    real(wp) :: f45(2) = 0.0_wp
    !> Rocker on link 4 at E (frame 2), N.
    real(wp) :: f43(2) = 0.0_wp
    !> Frame on rocker at D (frame 1), N.
    real(wp) :: f36(2) = 0.0_wp
    !> Link 2 on rocker at C (frame 1), N.
    real(wp) :: f32(2) = 0.0_wp
    !> Crank on link 2 at B (frame 1), N.
    real(wp) :: f21(2) = 0.0_wp
    !> Frame on crank at A (frame 1), N.
    real(wp) :: f16(2) = 0.0_wp
    !> Driving moment on the crank, N*m, counter-clockwise in frame 1 positive.
    real(wp) :: m1 = 0.0_wp
    !> The same from the power balance (virtual work), N*m.
    real(wp) :: m1_power = 0.0_wp
    !> Largest relative equilibrium residual of links 1..5.
    real(wp) :: residual = 0.0_wp
    !> Relative mismatch |M1 - M1_power| / scale.
    real(wp) :: mismatch = 0.0_wp
  end type sixbar_step_t

contains

  !> The acceleration a_q omega1^2 + v_q eps1 of a coordinate (a point's x or y, an angle)
  !> whose velocity and acceleration transfer functions are v_q and a_q (a_q omega1^2 alone
  !> at constant speed), m/s^2 or rad/s^2.
  elemental function sixbar_accel(a_q, v_q, omega1, eps1) result(acc)
    !> Acceleration transfer function (d2/dphi1^2 of the coordinate), m or rad.
    real(wp), intent(in) :: a_q
    !> Velocity transfer function (d/dphi1 of the coordinate), m or rad.
    real(wp), intent(in) :: v_q
    !> Crank speed, rad/s.
    real(wp), intent(in) :: omega1
    !> Crank angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps1
    real(wp) :: acc
    acc = a_q * omega1**2
    if (eps1 /= 0.0_wp) acc = acc + v_q * eps1
  end function sixbar_accel

  !> A vector given in frame 2 expressed in frame 1 (turned by beta - 180 deg).
  pure function sixbar_frame2_to_frame1(p, v2) result(v1)
    !> Mechanism data (a, b).
    type(sixbar_params_t), intent(in) :: p
    !> Vector in frame 2 (any unit).
    real(wp), intent(in) :: v2(2)
    real(wp) :: v1(2)
    real(wp) :: cb, sb
    call beta_cos_sin(p, cb, sb)
    v1 = [-cb * v2(1) + sb * v2(2), -sb * v2(1) - cb * v2(2)]
  end function sixbar_frame2_to_frame1

  !> A vector given in frame 1 expressed in frame 2 (turned by 180 deg - beta).
  pure function sixbar_frame1_to_frame2(p, v1) result(v2)
    !> Mechanism data (a, b).
    type(sixbar_params_t), intent(in) :: p
    !> Vector in frame 1 (any unit).
    real(wp), intent(in) :: v1(2)
    real(wp) :: v2(2)
    real(wp) :: cb, sb
    call beta_cos_sin(p, cb, sb)
    v2 = [-cb * v1(1) - sb * v1(2), sb * v1(1) - cb * v1(2)]
  end function sixbar_frame1_to_frame2

  !> Unit vector of gravity (-y0) in frame 1 (x1 along AD at atan2(b, a) in frame 0).
  pure function sixbar_down1(p) result(down)
    !> Mechanism data (a, b).
    type(sixbar_params_t), intent(in) :: p
    real(wp) :: down(2)
    real(wp) :: l_ad
    l_ad = hypot(p%a, p%b)
    down = [-p%b / l_ad, -p%a / l_ad]
  end function sixbar_down1

  !> Unit vector of gravity in frame 2 (carried from frame 1; (1, 0) up to roundoff).
  pure function sixbar_down2(p) result(down)
    !> Mechanism data (a, b).
    type(sixbar_params_t), intent(in) :: p
    real(wp) :: down(2)
    down = sixbar_frame1_to_frame2(p, sixbar_down1(p))
  end function sixbar_down2

  !> cos(beta), sin(beta) with beta = atan2(a, b).
  pure subroutine beta_cos_sin(p, cb, sb)
    type(sixbar_params_t), intent(in) :: p
    real(wp), intent(out) :: cb, sb
    real(wp) :: l_ad
    l_ad = hypot(p%a, p%b)
    cb = p%b / l_ad
    sb = p%a / l_ad
  end subroutine beta_cos_sin

  !> Crank angle (frame 1, rad) of the extreme position B0 with crank and connecting rod
  !> stretched in line (angle B0AD, C above x1, the branch `sixbar_position` uses);
  !> `ok` is false when that position does not exist.
  pure subroutine sixbar_extreme_phi1(p, phi1, ok)
    !> Mechanism data.
    type(sixbar_params_t), intent(in) :: p
    !> Crank angle of the extreme position, rad, in (0, pi).
    real(wp), intent(out) :: phi1
    !> Whether crank and connecting rod can lie in line.
    logical, intent(out) :: ok
    real(wp) :: l_ad, l_ac, l3, cos_cad
    l_ad = hypot(p%a, p%b)
    l_ac = p%l1 * (1.0_wp + p%lam2)
    l3 = p%lam3 * p%l1
    cos_cad = (l_ad**2 + l_ac**2 - l3**2) / (2.0_wp * l_ad * l_ac)
    ok = abs(cos_cad) < 1.0_wp
    phi1 = 0.0_wp
    if (ok) phi1 = acos(cos_cad)
  end subroutine sixbar_extreme_phi1

  !> Positions and transfer functions at crank angle `phi1` (rad, frame 1).
  !> Branches: C such that D-B-C turns clockwise (phi3 near 90 deg in the manual's example),
  !> cos(phi4) > 0 (H farther down the guide than E). A failure sets `status`.
  pure function sixbar_position(p, phi1) result(pos)
    !> Mechanism data.
    type(sixbar_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    type(sixbar_position_t) :: pos
    real(wp) :: l_ad, l2, l3, l_de, l4, ecc, beta, db(2), d_bd, cos_g, s32, c32, s13, c13, s12, c12
    real(wp) :: psi, sin4, cos4, e1(2), e2(2), e3(2), e_psi(2), e4(2), num2
    real(wp) :: v_eq(2), a_eq(2)

    l_ad = hypot(p%a, p%b)
    l2 = p%lam2 * p%l1
    l3 = p%lam3 * p%l1
    l_de = p%lam_de * p%l1
    l4 = p%lam4 * p%l1
    ecc = p%lam_e * p%l1
    beta = atan2(p%a, p%b)
    pos%phi1 = phi1

    ! contour A-B-C-D (frame 1): C on the circle about B (l2) and about D (l3)
    e1 = unit_at(phi1)
    pos%b = p%l1 * e1
    pos%d = [l_ad, 0.0_wp]
    db = pos%b - pos%d
    d_bd = hypot(db(1), db(2))
    if (d_bd > 0.0_wp) then
      cos_g = (l3**2 + d_bd**2 - l2**2) / (2.0_wp * l3 * d_bd)
    else
      cos_g = huge(1.0_wp)
    end if
    if (.not. abs(cos_g) <= 1.0_wp) then
      pos%status = sixbar_open1
      pos%detail = d_bd
      return
    end if
    pos%phi3 = modulo(atan2(db(2), db(1)) - acos(cos_g) + pi, 2.0_wp * pi) - pi
    e3 = unit_at(pos%phi3)
    pos%c = pos%d + l3 * e3
    pos%phi2 = atan2(pos%c(2) - pos%b(2), pos%c(1) - pos%b(1))
    e2 = unit_at(pos%phi2)
    s32 = sin(pos%phi3 - pos%phi2)
    c32 = cos(pos%phi3 - pos%phi2)
    if (abs(s32) < sixbar_dead_tol) then
      pos%status = sixbar_dead1
      pos%detail = s32
      return
    end if
    s13 = sin(phi1 - pos%phi3)
    c13 = cos(phi1 - pos%phi3)
    s12 = sin(phi1 - pos%phi2)
    c12 = cos(phi1 - pos%phi2)
    pos%u21 = s13 / (p%lam2 * s32)
    pos%u31 = s12 / (p%lam3 * s32)
    if (p%legacy_eq2) then
      num2 = c12 + p%lam2 * pos%u21**2 * c32 - p%lam3 * pos%u31**2
    else
      num2 = c13 + p%lam2 * pos%u21**2 * c32 - p%lam3 * pos%u31**2
    end if
    pos%eps_q2 = num2 / (p%lam2 * s32)
    pos%eps_q3 = (c12 + p%lam2 * pos%u21**2 - p%lam3 * pos%u31**2 * c32) / (p%lam3 * s32)
    pos%s2 = pos%b + p%lam_s2 * l2 * e2
    pos%v_s2q = p%l1 * perp(e1) + p%lam_s2 * l2 * pos%u21 * perp(e2)
    pos%a_s2q = -p%l1 * e1 + p%lam_s2 * l2 * (pos%eps_q2 * perp(e2) - pos%u21**2 * e2)

    ! contour D-E-H (frame 2): DE at psi = phi3 - beta, H on the guide y2 = e
    psi = pos%phi3 - beta
    e_psi = unit_at(psi)
    pos%e = l_de * e_psi
    pos%e1 = pos%d + sixbar_frame2_to_frame1(p, pos%e)
    sin4 = (ecc - pos%e(2)) / l4
    if (.not. abs(sin4) <= 1.0_wp) then
      pos%status = sixbar_open2
      pos%detail = abs(ecc - pos%e(2))
      return
    end if
    cos4 = sqrt((1.0_wp - sin4) * (1.0_wp + sin4))
    if (cos4 < sixbar_dead_tol) then
      pos%status = sixbar_dead2
      pos%detail = cos4
      return
    end if
    pos%phi4 = atan2(sin4, cos4)
    e4 = [cos4, sin4]
    pos%h = [pos%e(1) + l4 * cos4, ecc]
    pos%u41 = -p%lam_de * e_psi(1) * pos%u31 / (p%lam4 * cos4)
    pos%eps_q4 = (p%lam_de * (e_psi(2) * pos%u31**2 - e_psi(1) * pos%eps_q3) + p%lam4 * sin4 * pos%u41**2) &
                 / (p%lam4 * cos4)
    v_eq = l_de * pos%u31 * perp(e_psi)
    a_eq = l_de * (pos%eps_q3 * perp(e_psi) - pos%u31**2 * e_psi)
    pos%s4 = pos%e + p%lam_s4 * l4 * e4
    pos%v_s4q = v_eq + p%lam_s4 * l4 * pos%u41 * perp(e4)
    pos%a_s4q = a_eq + p%lam_s4 * l4 * (pos%eps_q4 * perp(e4) - pos%u41**2 * e4)
    pos%v_hq = v_eq + l4 * pos%u41 * perp(e4)
    pos%a_hq = a_eq + l4 * (pos%eps_q4 * perp(e4) - pos%u41**2 * e4)
  end function sixbar_position

  !> Kinetostatic analysis at crank angle `phi1` (rad, frame 1) with slider load `f5`
  !> (N, along +x2), at the deck's constant crank speed or at a given `omega1`, `eps1` (the true
  !> motion: then the crank's inertia moment -(j1 + j_input) eps1 acts on it). A position
  !> failure is returned in `status` with nothing computed.
  pure function sixbar_step(p, phi1, f5, omega1, eps1, j_input) result(step)
    !> Mechanism data.
    type(sixbar_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Slider load, N, signed along +x2.
    real(wp), intent(in) :: f5
    !> Crank speed, rad/s (default p%omega1).
    real(wp), intent(in), optional :: omega1
    !> Crank acceleration, rad/s^2 (default 0).
    real(wp), intent(in), optional :: eps1
    !> Moment of inertia turning with the crank besides the crank's own j1 (flywheel, rotor),
    !> kg*m^2 (default 0).
    real(wp), intent(in), optional :: j_input
    type(sixbar_step_t) :: step
    type(sixbar_position_t) :: pos
    real(wp) :: w2, down1(2), down2(2), zero2(2)
    real(wp) :: g1(2), g2(2), g3(2), g4(2), g5(2), phi2_f(2), phi4_f(2), phi5_f(2), f_load(2)
    real(wp) :: m_phi2, m_phi3, m_phi4, load5(2), f56v(2), f34(2), r1(2), r2(2), det, m3c, m23b
    real(wp) :: f12(2), terms(8), m_input
    type(link_balance_t) :: links(5)

    pos = sixbar_position(p, phi1)
    step%status = pos%status
    step%pos = pos
    step%f5 = f5
    if (pos%status /= sixbar_ok) return
    step%omega1 = p%omega1
    if (present(omega1)) step%omega1 = omega1
    if (present(eps1)) step%eps1 = eps1
    m_input = 0.0_wp
    if (present(eps1)) m_input = inertia_moment(p%j1 + merge_or_zero(j_input), step%eps1)
    w2 = step%omega1**2
    down1 = sixbar_down1(p)
    down2 = sixbar_down2(p)
    zero2 = 0.0_wp

    ! loads: gravity carried into frames 1 and 2, d'Alembert inertia (omega1 const, eps1 = 0;
    ! S1 = A and S3 = D are fixed, so links 1 and 3 have no inertia force)
    step%eps = [pos%eps_q2, pos%eps_q3, pos%eps_q4] * w2
    if (present(eps1)) step%eps = step%eps + [pos%u21, pos%u31, pos%u41] * step%eps1
    g1 = gravity_force(p%m1, p%g, down1)
    g2 = gravity_force(p%m2, p%g, down1)
    g3 = gravity_force(p%m3, p%g, down1)
    g4 = gravity_force(p%m4, p%g, down2)
    g5 = gravity_force(p%m5, p%g, down2)
    phi2_f = inertia_force(p%m2, sixbar_accel(pos%a_s2q, pos%v_s2q, step%omega1, step%eps1))
    phi4_f = inertia_force(p%m4, sixbar_accel(pos%a_s4q, pos%v_s4q, step%omega1, step%eps1))
    phi5_f = inertia_force(p%m5, [sixbar_accel(pos%a_hq(1), pos%v_hq(1), step%omega1, step%eps1), 0.0_wp])
    m_phi2 = inertia_moment(p%j2, step%eps(2))
    m_phi3 = inertia_moment(p%j3, step%eps(3))
    m_phi4 = inertia_moment(p%j4, step%eps(4))
    f_load = [f5, 0.0_wp]

    ! group 4-5 (frame 2): moments of links 4+5 about E give F56 (normal to the guide,
    ! through H); the slider's projections give F54; link 4's give F43
    load5 = f_load + g5 + phi5_f
    step%m54e = cross(pos%h - pos%e, load5) + cross(pos%s4 - pos%e, g4 + phi4_f) + m_phi4
    step%f56 = -step%m54e / (pos%h(1) - pos%e(1))
    f56v = [0.0_wp, step%f56]
    step%f54 = -(load5 + f56v)
    step%f45 = -step%f54
    step%f43 = -(step%f45 + g4 + phi4_f)

    ! group 2-3 (frame 1): F34 = -F43 carried from frame 2; formulas (5), (6) of section 1:
    ! moments of link 3 about C and of links 2+3 about B give F36 (2x2, det = l2*l3*sin(phi3-phi2))
    f34 = sixbar_frame2_to_frame1(p, -step%f43)
    m3c = cross(pos%e1 - pos%c, f34) + cross(pos%d - pos%c, g3) + m_phi3
    m23b = cross(pos%e1 - pos%b, f34) + cross(pos%d - pos%b, g3) + m_phi3 &
           + cross(pos%s2 - pos%b, g2 + phi2_f) + m_phi2
    r1 = pos%d - pos%c
    r2 = pos%d - pos%b
    det = cross(r1, r2)
    step%f36 = [(m23b * r1(1) - m3c * r2(1)) / det, (m23b * r1(2) - m3c * r2(2)) / det]
    step%f32 = -(step%f36 + f34 + g3)
    step%f21 = step%f32 - g2 - phi2_f

    ! crank 1: F16 and the driving moment M1 (moments about A)
    f12 = -step%f21
    step%f16 = -(f12 + g1)
    step%m1 = -cross(pos%b, f12) - m_input

    ! self-check 1: equilibrium residual of every link with the computed reactions
    links(1) = link_balance(reshape([zero2, pos%b, zero2], [2, 3]), &
                            reshape([step%f16, f12, g1], [2, 3]), [step%m1, m_input])
    links(2) = link_balance(reshape([pos%b, pos%c, pos%s2, pos%s2], [2, 4]), &
                            reshape([step%f21, -step%f32, g2, phi2_f], [2, 4]), [m_phi2])
    links(3) = link_balance(reshape([pos%d, pos%c, pos%e1, pos%d], [2, 4]), &
                            reshape([step%f36, step%f32, f34, g3], [2, 4]), [m_phi3])
    links(4) = link_balance(reshape([pos%e, pos%h, pos%s4, pos%s4], [2, 4]), &
                            reshape([step%f43, step%f45, g4, phi4_f], [2, 4]), [m_phi4])
    links(5) = link_balance(reshape([pos%h, pos%h, pos%h, pos%h, pos%h], [2, 5]), &
                            reshape([step%f54, f56v, f_load, g5, phi5_f], [2, 5]), [real(wp) ::])
    step%residual = equilibrium_residual(links)

    ! self-check 2: M1 from virtual work, M1 + sum(F . v_q) + sum(M . u) = 0 (analogues;
    ! each load with the velocity analogue of its point in its own frame)
    terms(1) = dot_product(g2 + phi2_f, pos%v_s2q)
    terms(2) = m_phi2 * pos%u21
    terms(3) = m_phi3 * pos%u31
    terms(4) = dot_product(g4 + phi4_f, pos%v_s4q)
    terms(5) = m_phi4 * pos%u41
    terms(6) = dot_product(load5, pos%v_hq)
    terms(7) = dot_product(g1 + g3, zero2)
    terms(8) = m_input
    step%m1_power = -sum(terms)
    step%mismatch = power_mismatch(step%m1, step%m1_power, sum(abs(terms)), load_moment_scale(links))
  contains

    !> j_input, or 0 when absent.
    pure real(wp) function merge_or_zero(x)
      real(wp), intent(in), optional :: x
      merge_or_zero = 0.0_wp
      if (present(x)) merge_or_zero = x
    end function merge_or_zero
  end function sixbar_step

  !> The reduced quantities at crank angle `phi1` (rad) with the slider's load `f5` (N, along
  !> +x2), from the transfer functions (each in its own frame): J_red = j1 + m2 |v_S2q|^2 +
  !> j2 u21^2 + j3 u31^2 + m4 |v_S4q|^2 + j4 u41^2 + m5 v_Hq,x^2, dJ_red its derivative, M_red =
  !> gravity and f5 times their velocity analogues (result: [J_red kg*m^2, dJ_red kg*m^2/rad,
  !> M_red N*m]; zeros where the position fails, which the step reports).
  pure function sixbar_reduced(p, phi1, f5) result(red)
    !> Mechanism data.
    type(sixbar_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Load on the slider, N, along +x2.
    real(wp), intent(in) :: f5
    real(wp) :: red(3)
    red = sixbar_reduced_at(p, sixbar_position(p, phi1), f5)
  end function sixbar_reduced

  !> sixbar_reduced at a computed position `pos` (zeros where its status is not sixbar_ok).
  pure function sixbar_reduced_at(p, pos, f5) result(red)
    !> Mechanism data.
    type(sixbar_params_t), intent(in) :: p
    !> Positions and transfer functions at the crank angle.
    type(sixbar_position_t), intent(in) :: pos
    !> Load on the slider, N, along +x2.
    real(wp), intent(in) :: f5
    real(wp) :: red(3)
    red = 0.0_wp
    if (pos%status /= sixbar_ok) return
    red(1) = p%j1 + p%m2 * dot_product(pos%v_s2q, pos%v_s2q) + p%j2 * pos%u21**2 + p%j3 * pos%u31**2 + &
             p%m4 * dot_product(pos%v_s4q, pos%v_s4q) + p%j4 * pos%u41**2 + p%m5 * pos%v_hq(1)**2
    red(2) = 2.0_wp * (p%m2 * dot_product(pos%v_s2q, pos%a_s2q) + p%j2 * pos%u21 * pos%eps_q2 + &
                       p%j3 * pos%u31 * pos%eps_q3 + p%m4 * dot_product(pos%v_s4q, pos%a_s4q) + &
                       p%j4 * pos%u41 * pos%eps_q4 + p%m5 * pos%v_hq(1) * pos%a_hq(1))
    red(3) = dot_product(gravity_force(p%m2, p%g, sixbar_down1(p)), pos%v_s2q) + &
             dot_product(gravity_force(p%m4, p%g, sixbar_down2(p)), pos%v_s4q) + &
             dot_product([f5, 0.0_wp] + gravity_force(p%m5, p%g, sixbar_down2(p)), pos%v_hq)
  end function sixbar_reduced_at

end module kinetostat_sixbar
