!> PR 3207: six-bar slotted-link (shaper) mechanism of manual section 3.
!> Links: 1 crank AB, 2 block at B sliding on the lever, 3 slotted lever pivoted at C,
!> 4 block at D sliding in the ram's slot (parallel to x), 5 ram translating along y, 6 frame.
!> Frame: origin A, x from A to C pointing vertically down (gravity along +x).
!> Kinematics by transfer functions of the contour A-B-C-A; reactions in closed form;
!> self-check by per-link equilibrium residuals and the virtual-work value of M1.
module kinetostat_pr3207
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: unit_at, perp, cross, polar
  use kinetostat_loads, only: inertia_force, inertia_moment, gravity_force
  use kinetostat_selfcheck, only: link_balance_t, link_balance, equilibrium_residual, power_mismatch, &
    load_moment_scale
  implicit none
  private
  public :: pr3207_params_t, pr3207_position_t, pr3207_step_t
  public :: pr3207_position, pr3207_step, pr3207_reduced, pr3207_step_at, pr3207_reduced_at

  !> Unit vector of gravity in the PR 3207 frame (x points down).
  real(wp), parameter :: down(2) = [1.0_wp, 0.0_wp]
  !> Unit vector of the ram's travel (y).
  real(wp), parameter :: ram_axis(2) = [0.0_wp, 1.0_wp]

  !> Mechanism data (SI units, angles not included).
  type :: pr3207_params_t
    !> Crank length AB, m.
    real(wp) :: l_ab = 0.0_wp
    !> Centre distance AC, m.
    real(wp) :: l_ac = 0.0_wp
    !> Lever length CD, m.
    real(wp) :: l_cd = 0.0_wp
    !> Lever pivot C to its centre of mass S3, m.
    real(wp) :: l_cs3 = 0.0_wp
    !> Mass of the crank (centre of mass at A), kg.
    real(wp) :: m1 = 0.0_wp
    !> Mass of the lever, kg.
    real(wp) :: m3 = 0.0_wp
    !> Mass of the ram, kg.
    real(wp) :: m5 = 0.0_wp
    !> Lever's moment of inertia about S3, kg*m^2.
    real(wp) :: j3 = 0.0_wp
    !> Crank speed (constant), rad/s, CCW positive.
    real(wp) :: omega1 = 0.0_wp
    !> Gravity, m/s^2 (along +x).
    real(wp) :: g = 0.0_wp
  end type pr3207_params_t

  !> Positions and transfer functions (analogues, d/dphi1) at one crank angle.
  type :: pr3207_position_t
    !> Crank angle, rad.
    real(wp) :: phi1 = 0.0_wp
    !> Lever angle (C to B), rad.
    real(wp) :: phi3 = 0.0_wp
    !> Distance C to B along the lever, m.
    real(wp) :: l_cb = 0.0_wp
    !> d l_CB / d phi1, m/rad.
    real(wp) :: dl_cb = 0.0_wp
    !> u31 = d phi3 / d phi1.
    real(wp) :: u31 = 0.0_wp
    !> eps31 = d^2 phi3 / d phi1^2.
    real(wp) :: eps31 = 0.0_wp
    !> Crank pin B, m.
    real(wp) :: b(2) = 0.0_wp
    !> Lever's centre of mass S3, m.
    real(wp) :: s3(2) = 0.0_wp
    !> Lever's end D, m.
    real(wp) :: d(2) = 0.0_wp
    !> Velocity analogue of S3, m/rad.
    real(wp) :: v_s3q(2) = 0.0_wp
    !> Acceleration analogue of S3, m/rad^2.
    real(wp) :: a_s3q(2) = 0.0_wp
    !> Ram position y5, m.
    real(wp) :: y5 = 0.0_wp
    !> Ram velocity analogue d y5 / d phi1, m/rad.
    real(wp) :: v5q = 0.0_wp
    !> Ram acceleration analogue d^2 y5 / d phi1^2, m/rad^2.
    real(wp) :: a5q = 0.0_wp
  end type pr3207_position_t

  !> Results of one crank step (forces as (x, y) components in the A-frame).
  type :: pr3207_step_t
    !> Crank angle, rad.
    real(wp) :: phi1 = 0.0_wp
    !> Cutting force on the ram, N, signed along +y.
    real(wp) :: f5c = 0.0_wp
    !> Crank speed, rad/s.
    real(wp) :: omega1 = 0.0_wp
    !> Crank angular acceleration, rad/s^2.
    real(wp) :: eps1 = 0.0_wp
    !> Lever angular acceleration, rad/s^2.
    real(wp) :: eps3 = 0.0_wp
    !> Ram acceleration, m/s^2.
    real(wp) :: a5 = 0.0_wp
    !> Frame on crank at A, N.
    real(wp) :: f16(2) = 0.0_wp
    !> Crank on block 2 at B (= F32, on the lever from block 2), N.
    real(wp) :: f21(2) = 0.0_wp
    !> Frame on lever at C, N.
    real(wp) :: f36(2) = 0.0_wp
    !> Block 4 on lever at D, N (along y).
    real(wp) :: f34(2) = 0.0_wp
    !> Frame guide on ram, N (along x).
    real(wp) :: f56(2) = 0.0_wp
    !> Driving moment on the crank, N*m, CCW positive.
    real(wp) :: m1 = 0.0_wp
    !> The same from the power balance (virtual work), N*m.
    real(wp) :: m1_power = 0.0_wp
    !> Largest relative equilibrium residual of links 1..5.
    real(wp) :: residual = 0.0_wp
    !> Relative mismatch |M1 - M1_power| / scale.
    real(wp) :: mismatch = 0.0_wp
  end type pr3207_step_t

contains

  !> Positions and transfer functions of the contour A-B-C-A at crank angle `phi1` (rad).
  !> Needs l_ab < l_ac (then l_CB > 0 and phi3 lies in the II or III quadrant).
  pure function pr3207_position(p, phi1) result(pos)
    !> Mechanism data.
    type(pr3207_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    type(pr3207_position_t) :: pos
    real(wp) :: cb(2), e3(2), s13, c13

    pos%phi1 = phi1
    pos%b = polar(p%l_ab, phi1)
    cb = pos%b - [p%l_ac, 0.0_wp]
    pos%l_cb = hypot(cb(1), cb(2))
    pos%phi3 = atan2(cb(2), cb(1))
    s13 = sin(phi1 - pos%phi3)
    c13 = cos(phi1 - pos%phi3)
    pos%dl_cb = -p%l_ab * s13
    pos%u31 = p%l_ab / pos%l_cb * c13
    pos%eps31 = -(p%l_ab * s13 + 2.0_wp * pos%dl_cb * pos%u31) / pos%l_cb

    e3 = unit_at(pos%phi3)
    pos%s3 = [p%l_ac, 0.0_wp] + p%l_cs3 * e3
    pos%d = [p%l_ac, 0.0_wp] + p%l_cd * e3
    pos%v_s3q = p%l_cs3 * pos%u31 * perp(e3)
    pos%a_s3q = p%l_cs3 * (pos%eps31 * perp(e3) - pos%u31**2 * e3)
    pos%y5 = pos%d(2)
    pos%v5q = p%l_cd * pos%u31 * e3(1)
    pos%a5q = p%l_cd * (pos%eps31 * e3(1) - pos%u31**2 * e3(2))
  end function pr3207_position

  !> Kinetostatic analysis at crank angle `phi1` (rad) with cutting force `f5c` (N, along +y)
  !> at the deck's constant crank speed (pr3207_step_at takes the true motion's speed).
  pure function pr3207_step(p, phi1, f5c) result(step)
    !> Mechanism data.
    type(pr3207_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Cutting force on the ram, N, signed along +y.
    real(wp), intent(in) :: f5c
    type(pr3207_step_t) :: step
    step = pr3207_step_at(p, pr3207_position(p, phi1), f5c)
  end function pr3207_step

  !> pr3207_step at a computed position `pos` (of crank angle pos%phi1): a run that needs the
  !> position for more than one analysis of a step computes it once. With `omega1` and `eps1`
  !> of the true motion, the inertia `j_input` (kg*m^2: flywheel and rotor) turning with the
  !> crank adds its inertia moment -j_input*eps1.
  pure function pr3207_step_at(p, pos, f5c, omega1, eps1, j_input) result(step)
    !> Mechanism data.
    type(pr3207_params_t), intent(in) :: p
    !> Positions and transfer functions at the crank angle.
    type(pr3207_position_t), intent(in) :: pos
    !> Cutting force on the ram, N, signed along +y.
    real(wp), intent(in) :: f5c
    !> Crank speed, rad/s (default p%omega1).
    real(wp), intent(in), optional :: omega1
    !> Crank acceleration, rad/s^2 (default 0).
    real(wp), intent(in), optional :: eps1
    !> Moment of inertia turning with the crank besides its links, kg*m^2 (default 0).
    real(wp), intent(in), optional :: j_input
    type(pr3207_step_t) :: step
    real(wp) :: w2, a_s3(2), g1(2), g3(2), g5(2), phi3_f(2), phi5_f(2), m_phi3, f_cut(2)
    real(wp) :: a(2), c(2), e3(2), n32, f32(2), f12(2), m_input
    type(link_balance_t) :: links(5)
    real(wp) :: terms(5)

    step%omega1 = p%omega1
    if (present(omega1)) step%omega1 = omega1
    if (present(eps1)) step%eps1 = eps1
    m_input = 0.0_wp
    if (present(j_input)) m_input = inertia_moment(j_input, step%eps1)
    w2 = step%omega1**2
    a = 0.0_wp
    c = [p%l_ac, 0.0_wp]
    e3 = unit_at(pos%phi3)
    step%phi1 = pos%phi1
    step%f5c = f5c

    ! loads: gravity along +x, d'Alembert inertia (crank's centre of mass at A)
    step%eps3 = pos%eps31 * w2 + pos%u31 * step%eps1
    step%a5 = pos%a5q * w2 + pos%v5q * step%eps1
    a_s3 = pos%a_s3q * w2 + pos%v_s3q * step%eps1
    g1 = gravity_force(p%m1, p%g, down)
    g3 = gravity_force(p%m3, p%g, down)
    g5 = gravity_force(p%m5, p%g, down)
    phi3_f = inertia_force(p%m3, a_s3)
    m_phi3 = inertia_moment(p%j3, step%eps3)
    phi5_f = inertia_force(p%m5, step%a5 * ram_axis)
    f_cut = f5c * ram_axis

    ! group 4-5: the ram's guide takes x, the slot of the ram (parallel to x) passes y to D
    step%f56 = -g5
    step%f34 = [0.0_wp, f_cut(2) + phi5_f(2)]

    ! group 2-3: block 2 presses normal to the lever at B; moments of lever 3 about C
    n32 = -(cross(pos%d - c, step%f34) + cross(pos%s3 - c, g3 + phi3_f) + m_phi3) / pos%l_cb
    f32 = n32 * perp(e3)
    step%f21 = f32
    step%f36 = -(f32 + step%f34 + g3 + phi3_f)

    ! crank 1
    f12 = -step%f21
    step%f16 = -(f12 + g1)
    step%m1 = -cross(pos%b - a, f12) - m_input

    ! self-check 1: equilibrium residual of every link with the computed reactions
    links(1) = link_balance(reshape([a, pos%b, a], [2, 3]), &
                            reshape([step%f16, f12, g1], [2, 3]), [step%m1, m_input])
    links(2) = link_balance(reshape([pos%b, pos%b], [2, 2]), &
                            reshape([step%f21, -f32], [2, 2]), [real(wp) ::])
    links(3) = link_balance(reshape([c, pos%b, pos%d, pos%s3, pos%s3], [2, 5]), &
                            reshape([step%f36, f32, step%f34, g3, phi3_f], [2, 5]), [m_phi3])
    links(4) = link_balance(reshape([pos%d, pos%d], [2, 2]), &
                            reshape([-step%f34, step%f34], [2, 2]), [real(wp) ::])
    ! ram: force equations only (its moment equation holds through the unreported guide moment)
    links(5) = link_balance(reshape([pos%d, pos%d, pos%d, pos%d, pos%d], [2, 5]), &
                            reshape([-step%f34, step%f56, f_cut, g5, phi5_f], [2, 5]), [real(wp) ::])
    step%residual = equilibrium_residual(links)

    ! self-check 2: M1 from virtual work, M1 + sum(F . v_q) + sum(M . u) = 0 (analogues)
    terms(1) = dot_product(g3 + phi3_f, pos%v_s3q)
    terms(2) = m_phi3 * pos%u31
    terms(3) = dot_product(f_cut + phi5_f + g5, pos%v5q * ram_axis)
    terms(4) = dot_product(g1, [0.0_wp, 0.0_wp])
    terms(5) = m_input
    step%m1_power = -sum(terms)
    step%mismatch = power_mismatch(step%m1, step%m1_power, sum(abs(terms)), load_moment_scale(links))
  end function pr3207_step_at

  !> The reduced quantities at crank angle `phi1` (rad) with cutting force `f5c` (N, along
  !> +y), from the transfer functions: J_red = m3 |v_S3q|^2 + j3 u31^2 + m5 v5q^2 (the crank's
  !> centre of mass is at its pivot; the blocks are massless), dJ_red = its derivative
  !> (2 m v_q . a_q + 2 j u eps_q), M_red = gravity and the cutting force times their
  !> velocity analogues (result: [J_red kg*m^2, dJ_red kg*m^2/rad, M_red N*m]).
  pure function pr3207_reduced(p, phi1, f5c) result(red)
    !> Mechanism data.
    type(pr3207_params_t), intent(in) :: p
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Cutting force on the ram, N, along +y.
    real(wp), intent(in) :: f5c
    real(wp) :: red(3)
    red = pr3207_reduced_at(p, pr3207_position(p, phi1), f5c)
  end function pr3207_reduced

  !> pr3207_reduced at a computed position `pos`.
  pure function pr3207_reduced_at(p, pos, f5c) result(red)
    !> Mechanism data.
    type(pr3207_params_t), intent(in) :: p
    !> Positions and transfer functions at the crank angle.
    type(pr3207_position_t), intent(in) :: pos
    !> Cutting force on the ram, N, along +y.
    real(wp), intent(in) :: f5c
    real(wp) :: red(3)
    red(1) = p%m3 * dot_product(pos%v_s3q, pos%v_s3q) + p%j3 * pos%u31**2 + p%m5 * pos%v5q**2
    red(2) = 2.0_wp * (p%m3 * dot_product(pos%v_s3q, pos%a_s3q) + p%j3 * pos%u31 * pos%eps31 + &
                       p%m5 * pos%v5q * pos%a5q)
    red(3) = dot_product(gravity_force(p%m3, p%g, down), pos%v_s3q) + &
             dot_product(gravity_force(p%m5, p%g, down) + f5c * ram_axis, pos%v5q * ram_axis)
  end function pr3207_reduced_at

end module kinetostat_pr3207
