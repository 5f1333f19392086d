!> PR 3050: four-bar with an oscillating hydraulic cylinder, manual section 4.
!> Links: 1 hydraulic cylinder pivoted on the frame at A, 2 piston with rod sliding in 1 and
!> pinned at B to 3, 3 rocker (turning platform) pivoted on the frame at C, 4 frame.
!> Frame: origin C, x from C to A, y counter-clockwise. Links 1 and 2 turn together (phi1 = phi2).
!> The rocker's motion is prescribed (phi3, omega3, eps3 per step); the oil force F2 drives.
!> Kinematics by transfer functions of the contour C-B-A (w.r.t. phi3); reactions in closed
!> form in the manual's order; self-check by per-link equilibrium residuals and the power
!> balance of F2 written with analogues (valid also where omega3 = 0).
module kinetostat_pr3050
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_vec2, only: unit_at, perp, cross, polar
  use kinetostat_loads, only: inertia_force, inertia_moment, gravity_force
  use kinetostat_selfcheck, only: link_balance_t, link_balance, equilibrium_residual, power_mismatch
  implicit none
  private
  public :: pr3050_params_t, pr3050_position_t, pr3050_step_t
  public :: pr3050_position, pr3050_check_position, pr3050_step
  public :: pr3050_min_length_rel, pr3050_dead_sin

  !> Smallest cylinder length s, relative to l_CA + l_CB, that counts as assembled.
  real(wp), parameter :: pr3050_min_length_rel = 1.0e-9_wp
  !> |sin(phi3 - phi2)| at or below this is a dead position (cylinder axis through C).
  real(wp), parameter :: pr3050_dead_sin = 1.0e-9_wp

  !> Mechanism data (SI units, angles in rad).
  type :: pr3050_params_t
    !> Centre distance C-A, m.
    real(wp) :: l_ca = 0.0_wp
    !> Rocker arm C-B, m.
    real(wp) :: l_cb = 0.0_wp
    !> C to the rocker's centre of mass S3, m.
    real(wp) :: l_cs3 = 0.0_wp
    !> Angle of CS3 ahead of CB (counter-clockwise), rad.
    real(wp) :: delta = 0.0_wp
    !> B to the rod's centre of mass S2, along the rod towards A, m.
    real(wp) :: l_bs2 = 0.0_wp
    !> The cylinder's centre of mass S1 to A, along the axis (S1 between A and B), m.
    real(wp) :: l_s1a = 0.0_wp
    !> Direction of gravity in the C-A frame, rad.
    real(wp) :: gamma = 0.0_wp
    !> Gravity, m/s^2.
    real(wp) :: g = 0.0_wp
    !> Mass of the cylinder 1, kg.
    real(wp) :: m1 = 0.0_wp
    !> Mass of the rod with piston 2, kg.
    real(wp) :: m2 = 0.0_wp
    !> Mass of the rocker 3, kg.
    real(wp) :: m3 = 0.0_wp
    !> Cylinder's moment of inertia about S1, kg*m^2.
    real(wp) :: j1 = 0.0_wp
    !> Rod's moment of inertia about S2, kg*m^2.
    real(wp) :: j2 = 0.0_wp
    !> Rocker's moment of inertia about S3, kg*m^2.
    real(wp) :: j3 = 0.0_wp
  end type pr3050_params_t

  !> Positions and transfer functions (analogues, d/dphi3) at one rocker angle.
  type :: pr3050_position_t
    !> Rocker angle (C to B), rad.
    real(wp) :: phi3 = 0.0_wp
    !> Cylinder axis angle (B to A), rad; phi1 = phi2.
    real(wp) :: phi2 = 0.0_wp
    !> Cylinder length s = |A - B|, m.
    real(wp) :: s = 0.0_wp
    !> s' = ds/dphi3, m/rad.
    real(wp) :: ds = 0.0_wp
    !> s'' = d^2 s/dphi3^2, m/rad^2.
    real(wp) :: dds = 0.0_wp
    !> u23 = dphi2/dphi3.
    real(wp) :: u23 = 0.0_wp
    !> eps23 = d^2 phi2/dphi3^2, 1/rad.
    real(wp) :: eps23 = 0.0_wp
    !> Pivot A of the cylinder, m.
    real(wp) :: a(2) = 0.0_wp
    !> Pin B between rod and rocker, m.
    real(wp) :: b(2) = 0.0_wp
    !> Unit vector of the cylinder axis, B to A.
    real(wp) :: e2(2) = 0.0_wp
    !> Centre of mass S1 of the cylinder, m.
    real(wp) :: s1(2) = 0.0_wp
    !> Centre of mass S2 of the rod, m.
    real(wp) :: s2(2) = 0.0_wp
    !> Centre of mass S3 of the rocker, m.
    real(wp) :: s3(2) = 0.0_wp
    !> Velocity analogue of S1, m/rad.
    real(wp) :: v_s1q(2) = 0.0_wp
    !> Velocity analogue of S2, m/rad.
    real(wp) :: v_s2q(2) = 0.0_wp
    !> Velocity analogue of S3, m/rad.
    real(wp) :: v_s3q(2) = 0.0_wp
    !> Acceleration analogue of S1, m/rad^2.
    real(wp) :: a_s1q(2) = 0.0_wp
    !> Acceleration analogue of S2, m/rad^2.
    real(wp) :: a_s2q(2) = 0.0_wp
    !> Acceleration analogue of S3, m/rad^2.
    real(wp) :: a_s3q(2) = 0.0_wp
  end type pr3050_position_t

  !> Results of one rocker step (forces as (x, y) components in the C-A frame).
  type :: pr3050_step_t
    !> Rocker angle, rad.
    real(wp) :: phi3 = 0.0_wp
    !> Rocker angular speed, rad/s.
    real(wp) :: omega3 = 0.0_wp
    !> Rocker angular acceleration, rad/s^2.
    real(wp) :: eps3 = 0.0_wp
    !> Cylinder axis angle (B to A), rad; phi1 = phi2.
    real(wp) :: phi2 = 0.0_wp
    !> Cylinder length s, m.
    real(wp) :: s = 0.0_wp
    !> Extension rate ds/dt = s'*omega3, m/s.
    real(wp) :: s_dot = 0.0_wp
    !> Angular speed of cylinder and rod, omega1 = omega2 = u23*omega3, rad/s.
    real(wp) :: omega2 = 0.0_wp
    !> Angular acceleration of cylinder and rod, eps1 = eps2 = eps23*omega3^2 + u23*eps3, rad/s^2.
    real(wp) :: eps2 = 0.0_wp
    !> Frame on cylinder at A, N.
    real(wp) :: f14(2) = 0.0_wp
    !> Frame on rocker at C, N.
    real(wp) :: f34(2) = 0.0_wp
    !> Rod on rocker at B, N.
    real(wp) :: f32(2) = 0.0_wp
    !> Prismatic pair: normal force on rod 2 from cylinder 1, N, signed along n2 = e2 turned +90 deg.
    real(wp) :: n21 = 0.0_wp
    !> Prismatic pair: moment on rod 2 from cylinder 1 with the normal force taken at B, N*m, CCW.
    real(wp) :: m21 = 0.0_wp
    !> Driving (oil) force on the rod along the axis, N, positive pushing the rod out (A to B).
    real(wp) :: f2 = 0.0_wp
    !> The same from the power balance (analogues), N.
    real(wp) :: f2_power = 0.0_wp
    !> Largest relative equilibrium residual of links 1, 2, 3.
    real(wp) :: residual = 0.0_wp
    !> Relative mismatch |F2 - F2_power| / scale.
    real(wp) :: mismatch = 0.0_wp
  end type pr3050_step_t

contains

  !> Positions and transfer functions of the contour C-B-A at rocker angle `phi3` (rad).
  !> B + s*e2 = A with e2 = (cos phi2, sin phi2); differentiating twice w.r.t. phi3 and
  !> projecting on e2 and on its normal gives s', u23, s'', eps23. Needs s > 0.
  pure function pr3050_position(p, phi3) result(pos)
    !> Mechanism data.
    type(pr3050_params_t), intent(in) :: p
    !> Rocker angle, rad.
    real(wp), intent(in) :: phi3
    type(pr3050_position_t) :: pos
    real(wp) :: ab(2), e3(2), e3d(2), n2(2), s32, c32

    pos%phi3 = phi3
    pos%a = [p%l_ca, 0.0_wp]
    e3 = unit_at(phi3)
    pos%b = p%l_cb * e3
    ab = pos%a - pos%b
    pos%s = hypot(ab(1), ab(2))
    pos%phi2 = atan2(ab(2), ab(1))
    pos%e2 = unit_at(pos%phi2)
    n2 = perp(pos%e2)
    s32 = sin(phi3 - pos%phi2)
    c32 = cos(phi3 - pos%phi2)
    pos%ds = p%l_cb * s32
    pos%u23 = -p%l_cb / pos%s * c32
    pos%eps23 = (p%l_cb * s32 - 2.0_wp * pos%ds * pos%u23) / pos%s
    pos%dds = p%l_cb * c32 + pos%s * pos%u23**2

    ! centres of mass and their analogues (d e2/dphi3 = u23*n2, d n2/dphi3 = -u23*e2)
    pos%s1 = pos%a - p%l_s1a * pos%e2
    pos%s2 = pos%b + p%l_bs2 * pos%e2
    e3d = unit_at(phi3 + p%delta)
    pos%s3 = p%l_cs3 * e3d
    pos%v_s1q = -p%l_s1a * pos%u23 * n2
    pos%a_s1q = -p%l_s1a * (pos%eps23 * n2 - pos%u23**2 * pos%e2)
    pos%v_s2q = p%l_cb * perp(e3) + p%l_bs2 * pos%u23 * n2
    pos%a_s2q = -p%l_cb * e3 + p%l_bs2 * (pos%eps23 * n2 - pos%u23**2 * pos%e2)
    pos%v_s3q = p%l_cs3 * perp(e3d)
    pos%a_s3q = -p%l_cs3 * e3d
  end function pr3050_position

  !> Whether the mechanism can be analysed at rocker angle `phi3` (rad): the cylinder has a
  !> length (s > 0) and the position is not dead (C, B, A not collinear: s' /= 0, else F2 and
  !> the reactions are undetermined). The message names the reason; the caller adds the step.
  pure subroutine pr3050_check_position(p, phi3, error)
    !> Mechanism data.
    type(pr3050_params_t), intent(in) :: p
    !> Rocker angle, rad.
    real(wp), intent(in) :: phi3
    !> Geometry error (exit 3) when the position cannot be analysed.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: ab(2), s
    ab = [p%l_ca, 0.0_wp] - polar(p%l_cb, phi3)
    s = hypot(ab(1), ab(2))
    if (.not. s > pr3050_min_length_rel * (p%l_ca + p%l_cb)) then
      call fatal_error(error, exit_geometry, "cannot be assembled: cylinder length s = 0 (B coincides with A)")
      return
    end if
    ! s*sin(phi3 - phi2) = l_CA*sin(phi3): the axis AB passes through C
    if (.not. abs(p%l_ca * sin(phi3)) / s > pr3050_dead_sin) then
      call fatal_error(error, exit_geometry, "dead position: C, B and A are collinear (s' = 0), "// &
        "the force F2 and the reactions are undetermined")
    end if
  end subroutine pr3050_check_position

  !> Kinetostatic analysis at rocker angle `phi3` (rad), speed `omega3` (rad/s) and angular
  !> acceleration `eps3` (rad/s^2). The position must pass pr3050_check_position.
  pure function pr3050_step(p, phi3, omega3, eps3) result(step)
    !> Mechanism data.
    type(pr3050_params_t), intent(in) :: p
    !> Rocker angle, rad.
    real(wp), intent(in) :: phi3
    !> Rocker angular speed, rad/s.
    real(wp), intent(in) :: omega3
    !> Rocker angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps3
    type(pr3050_step_t) :: step
    type(pr3050_position_t) :: pos
    real(wp) :: w2, down(2), c(2), n2(2), l1(2), l2(2), l3(2), g1(2), g2(2), g3(2)
    real(wp) :: m_phi1, m_phi2, m_phi3, m_a, m_a12, m_b3, f21n(2), oil_rod(2)
    type(link_balance_t) :: links(3)
    real(wp) :: terms(6)

    pos = pr3050_position(p, phi3)
    w2 = omega3**2
    c = 0.0_wp
    n2 = perp(pos%e2)
    step%phi3 = phi3
    step%omega3 = omega3
    step%eps3 = eps3
    step%phi2 = pos%phi2
    step%s = pos%s
    step%s_dot = pos%ds * omega3
    step%omega2 = pos%u23 * omega3
    step%eps2 = pos%eps23 * w2 + pos%u23 * eps3

    ! loads L_i = G_i + Phi_i at S_i, a = a_q*omega3^2 + v_q*eps3; M_Phi_i = -J_i*eps_i
    down = unit_at(p%gamma)
    g1 = gravity_force(p%m1, p%g, down)
    g2 = gravity_force(p%m2, p%g, down)
    g3 = gravity_force(p%m3, p%g, down)
    l1 = g1 + inertia_force(p%m1, pos%a_s1q * w2 + pos%v_s1q * eps3)
    l2 = g2 + inertia_force(p%m2, pos%a_s2q * w2 + pos%v_s2q * eps3)
    l3 = g3 + inertia_force(p%m3, pos%a_s3q * w2 + pos%v_s3q * eps3)
    m_phi1 = inertia_moment(p%j1, step%eps2)
    m_phi2 = inertia_moment(p%j2, step%eps2)
    m_phi3 = inertia_moment(p%j3, eps3)

    ! F34y: moments of links 1+2+3 about A (internal forces cancel): cross(C - A, F34) = -l_CA*F34y
    m_a = cross(pos%s1 - pos%a, l1) + m_phi1 + cross(pos%s2 - pos%a, l2) + m_phi2 &
          + cross(pos%s3 - pos%a, l3) + m_phi3
    step%f34(2) = m_a / p%l_ca
    ! F34x: moments of link 3 about B: cross(C - B, F34) = yB*F34x - xB*F34y
    m_b3 = cross(pos%s3 - pos%b, l3) + m_phi3
    step%f34(1) = (pos%b(1) * step%f34(2) - m_b3) / pos%b(2)
    ! F32: forces of link 3; F14: forces of links 1+2+3
    step%f32 = -(step%f34 + l3)
    step%f14 = -(l1 + l2 + l3 + step%f34)
    ! link 2: on it act F23 = -F32 at B, F21 (normal N21*n2 at B plus the moment M21),
    ! the oil force F2*(-e2) along the axis, and L2. F2: projection on e2; M21: moments about B.
    step%f2 = dot_product(pos%e2, l2 - step%f32)
    step%m21 = -(cross(pos%s2 - pos%b, l2) + m_phi2)
    ! N21: projection on n2, N21 = -n2.(L2 + F23), with n2.F23 = M_A12/s from the moments of
    ! links 1+2 about A (cross(B - A, F23) = -s*n2.F23); this avoids the cancellation of the
    ! large axial components in n2.F32 (the pair's force is nearly along the axis)
    m_a12 = cross(pos%s1 - pos%a, l1) + m_phi1 + cross(pos%s2 - pos%a, l2) + m_phi2
    step%n21 = -dot_product(n2, l2) - m_a12 / pos%s

    ! self-check 1: equilibrium residual of every link with the computed reactions
    f21n = step%n21 * n2
    oil_rod = -step%f2 * pos%e2
    links(1) = link_balance(reshape([pos%a, pos%b, pos%a, pos%s1], [2, 4]), &
                            reshape([step%f14, -f21n, -oil_rod, l1], [2, 4]), [-step%m21, m_phi1])
    links(2) = link_balance(reshape([pos%s2, pos%b, pos%b, pos%b], [2, 4]), &
                            reshape([l2, -step%f32, f21n, oil_rod], [2, 4]), [step%m21, m_phi2])
    links(3) = link_balance(reshape([c, pos%b, pos%s3], [2, 3]), &
                            reshape([step%f34, step%f32, l3], [2, 3]), [m_phi3])
    step%residual = equilibrium_residual(links)

    ! self-check 2: power balance divided by omega3 (analogues, also valid at omega3 = 0):
    ! F2*s' + sum (G_i + Phi_i).v_Siq + sum M_Phi_i*u_i3 = 0, u13 = u23, u33 = 1
    terms(1) = dot_product(l1, pos%v_s1q)
    terms(2) = dot_product(l2, pos%v_s2q)
    terms(3) = dot_product(l3, pos%v_s3q)
    terms(4) = m_phi1 * pos%u23
    terms(5) = m_phi2 * pos%u23
    terms(6) = m_phi3
    step%f2_power = -sum(terms) / pos%ds
    step%mismatch = power_mismatch(step%f2, step%f2_power, sum(abs(terms)) / abs(pos%ds), &
      maxval(links%scale_f))
  end function pr3050_step

end module kinetostat_pr3050
