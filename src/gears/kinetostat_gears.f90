!> Gear meshes (manual section 6): spur, helical and straight bevel pairs, a multi-stage
!> reducer of parallel shafts in series (fig. 18) and a single-row planetary gear with k
!> satellites (fig. 19). Friction-free, uniform rotation, no gravity or inertia: the mesh
!> force acts at the pitch point, in the transverse plane along the line of action.
!> Frame of a stage: origin at the driving gear's axis O1, x and y in the transverse plane,
!> moments counter-clockwise positive (about +z). Lengths in m, forces in N, torques in N*m.
module kinetostat_gears
  use kinetostat_kinds, only: wp, pi
  use kinetostat_vec2, only: unit_at, perp, cross
  use kinetostat_selfcheck, only: link_balance_t, link_balance, equilibrium_residual, &
    power_mismatch
  implicit none
  private
  public :: gear_spur, gear_helical, gear_bevel, gear_planetary, gear_kind_names
  public :: gear_stage_t, gear_result_t
  public :: gear_pair, gear_series, gear_planetary_step, mesh_components

  !> Stage kind: external spur pair.
  integer, parameter :: gear_spur = 1
  !> Stage kind: external helical pair.
  integer, parameter :: gear_helical = 2
  !> Stage kind: straight bevel pair (forces at the mean section).
  integer, parameter :: gear_bevel = 3
  !> Stage kind: single-row planetary gear (sun 1 input, fixed ring 3, carrier H output).
  integer, parameter :: gear_planetary = 4
  !> Stage kind names as written in decks (index = kind code).
  character(*), parameter :: gear_kind_names(4) = [character(len=9) :: &
    "spur", "helical", "bevel", "planetary"]

  !> Geometry of one stage (angles in rad, lengths in m).
  type :: gear_stage_t
    !> Kind code: gear_spur, gear_helical, gear_bevel or gear_planetary.
    integer :: kind = gear_spur
    !> Teeth of the driving gear (planetary: the sun).
    integer :: z1 = 0
    !> Teeth of the driven gear (planetary: a satellite).
    integer :: z2 = 0
    !> Planetary: teeth of the fixed ring gear (internal teeth).
    integer :: z3 = 0
    !> Planetary: number of satellites.
    integer :: k = 1
    !> Pitch (operating) diameter of gear 1, m (bevel: mean-section diameter d_m1).
    real(wp) :: dw1 = 0.0_wp
    !> Operating pressure angle alpha_w, rad (bevel: profile angle alpha).
    real(wp) :: alpha_w = 0.0_wp
    !> Planetary: operating pressure angle of the satellite-ring mesh, rad.
    real(wp) :: alpha_w23 = 0.0_wp
    !> Helical: helix angle beta, rad (signed: gives the sense of the axial force).
    real(wp) :: beta = 0.0_wp
    !> Bevel: pitch cone angle of gear 1, rad.
    real(wp) :: delta1 = 0.0_wp
    !> Direction of the centre line O1 -> O2 (planetary: to satellite 1), rad from x.
    real(wp) :: gamma = 0.0_wp
  end type gear_stage_t

  !> Results of one stage. Vectors are (x, y) in the stage frame; the mesh quantities
  !> Ft..Fn are magnitudes on gear 1 (planetary: one sun-satellite mesh).
  type :: gear_result_t
    !> Torque on the driving gear from its shaft, N*m, CCW positive.
    real(wp) :: m1 = 0.0_wp
    !> Pitch diameter of gear 2, m (bevel: mean diameter d_m2).
    real(wp) :: dw2 = 0.0_wp
    !> Ratio u: z2/z1 (planetary: u_1H = 1 + z3/z1).
    real(wp) :: u = 0.0_wp
    !> Tangential (circumferential) force F_t, N.
    real(wp) :: ft = 0.0_wp
    !> Radial force on gear 1, N.
    real(wp) :: fr1 = 0.0_wp
    !> Axial force on gear 1, N (helical: signed with beta).
    real(wp) :: fa1 = 0.0_wp
    !> Radial force on gear 2, N.
    real(wp) :: fr2 = 0.0_wp
    !> Axial force on gear 2, N.
    real(wp) :: fa2 = 0.0_wp
    !> Normal tooth force F_n, N.
    real(wp) :: fn = 0.0_wp
    !> Centre of gear 1, m.
    real(wp) :: o1(2) = 0.0_wp
    !> Centre of gear 2 (planetary: of satellite 1), m.
    real(wp) :: o2(2) = 0.0_wp
    !> Pitch point of the mesh (planetary: sun-satellite 1), m.
    real(wp) :: p(2) = 0.0_wp
    !> In-plane mesh force on gear 1 from gear 2, N (planetary: on the sun from satellite 1).
    real(wp) :: f12(2) = 0.0_wp
    !> Support reaction on the shaft of gear 1 (all its meshes), N.
    real(wp) :: fs1(2) = 0.0_wp
    !> Support reaction on the shaft of gear 2 (series: the resultant on the shared shaft;
    !> planetary: on the carrier's shaft), N.
    real(wp) :: fs2(2) = 0.0_wp
    !> Planetary: force on satellite 1 from the ring, N.
    real(wp) :: f23(2) = 0.0_wp
    !> Planetary: force on satellite 1 from the carrier, N.
    real(wp) :: f2h(2) = 0.0_wp
    !> Torque delivered to the shaft of gear 2 by the mesh forces, N*m, CCW positive
    !> (series: at the output of this stage; planetary: delivered by the carrier, M_H).
    real(wp) :: m2 = 0.0_wp
    !> The same from the power balance (friction-free), N*m.
    real(wp) :: m2_power = 0.0_wp
    !> Planetary: moment of the satellites' forces on the ring (the housing), N*m.
    real(wp) :: m_house = 0.0_wp
    !> Planetary: the same from the balance of the whole gear, M1 - M_H, N*m.
    real(wp) :: m_house_power = 0.0_wp
    !> Largest relative equilibrium residual of the stage's bodies.
    real(wp) :: residual = 0.0_wp
    !> Largest relative mismatch of M2 (and M_house) against the power balance.
    real(wp) :: mismatch = 0.0_wp
  end type gear_result_t

contains

  !> Scalar mesh components on gear 1 for torque `m1` (N*m) on gear 1: Ft = 2|M1|/dw1,
  !> radial, axial and normal forces of the stage kind (manual section 6).
  pure subroutine mesh_components(st, m1, ft, fr1, fa1, fr2, fa2, fn)
    !> Stage geometry.
    type(gear_stage_t), intent(in) :: st
    !> Torque on gear 1, N*m.
    real(wp), intent(in) :: m1
    !> Tangential force, N.
    real(wp), intent(out) :: ft
    !> Radial force on gear 1, N.
    real(wp), intent(out) :: fr1
    !> Axial force on gear 1, N.
    real(wp), intent(out) :: fa1
    !> Radial force on gear 2, N.
    real(wp), intent(out) :: fr2
    !> Axial force on gear 2, N.
    real(wp), intent(out) :: fa2
    !> Normal force, N.
    real(wp), intent(out) :: fn
    ft = 2.0_wp * abs(m1) / st%dw1
    select case (st%kind)
    case (gear_helical)
      fa1 = ft * tan(st%beta)
      fr1 = ft * tan(st%alpha_w) / cos(st%beta)
      fn = ft / (cos(st%alpha_w) * cos(st%beta))
      fr2 = fr1
      fa2 = fa1
    case (gear_bevel)
      fr1 = ft * tan(st%alpha_w) * cos(st%delta1)
      fa1 = ft * tan(st%alpha_w) * sin(st%delta1)
      fn = ft / cos(st%alpha_w)
      ! shaft angle 90 deg: delta2 = 90 deg - delta1, so Fr2 = Fa1 and Fa2 = Fr1
      fr2 = ft * tan(st%alpha_w) * cos(bevel_delta2(st))
      fa2 = ft * tan(st%alpha_w) * sin(bevel_delta2(st))
    case default
      fr1 = ft * tan(st%alpha_w)
      fa1 = 0.0_wp
      fn = ft / cos(st%alpha_w)
      fr2 = fr1
      fa2 = 0.0_wp
    end select
  end subroutine mesh_components

  !> Pitch cone angle of bevel gear 2 for a shaft angle of 90 deg: delta2 = 90 deg - delta1.
  pure real(wp) function bevel_delta2(st)
    type(gear_stage_t), intent(in) :: st
    bevel_delta2 = 0.5_wp * pi - st%delta1
  end function bevel_delta2

  !> In-plane mesh force on the driver (from the driven gear) for driver torque `m1`,
  !> centre-line direction `e` and radius `r1` (m): the tangential part opposes M1,
  !> the radial part `fr` pushes the driver away from the pitch point (towards its axis).
  pure function driver_force(m1, r1, fr, e) result(f)
    real(wp), intent(in) :: m1, r1, fr, e(2)
    real(wp) :: f(2)
    f = -(m1 / r1) * perp(e) - fr * e
  end function driver_force

  !> One pair with its driver at `o1` (m) under torque `m1` (N*m): mesh forces, the
  !> support reactions of both shafts, the torque delivered to gear 2 (M2 = -u*M1 for an
  !> external cylindrical pair: gear 2 turns the other way; bevel: M2 = u*M1 about its own
  !> axis) and its power-balance value.
  pure function gear_pair(st, m1, o1) result(r)
    !> Stage geometry (kind spur, helical or bevel).
    type(gear_stage_t), intent(in) :: st
    !> Torque on gear 1 from its shaft, N*m.
    real(wp), intent(in) :: m1
    !> Centre of gear 1, m.
    real(wp), intent(in) :: o1(2)
    type(gear_result_t) :: r
    real(wp) :: e(2), r1, r2, f21(2)
    type(link_balance_t) :: links(2)

    r%m1 = m1
    r%u = real(st%z2, wp) / real(st%z1, wp)
    r%dw2 = st%dw1 * r%u
    call mesh_components(st, m1, r%ft, r%fr1, r%fa1, r%fr2, r%fa2, r%fn)
    e = unit_at(st%gamma)
    r1 = 0.5_wp * st%dw1
    r2 = 0.5_wp * r%dw2
    r%o1 = o1
    r%o2 = o1 + (r1 + r2) * e
    r%p = o1 + r1 * e
    r%f12 = driver_force(m1, r1, r%fr1, e)
    f21 = -r%f12
    r%fs1 = -r%f12
    if (st%kind == gear_bevel) then
      ! gear 2's axis is not parallel: only the torque about its own axis is reported
      r%m2 = r%ft * r2 * sign(1.0_wp, m1)
      r%m2_power = m1 * r%u
      r%fs2 = 0.0_wp
      links(1) = link_balance(reshape([o1, r%p, o1], [2, 3]), reshape([r%fs1, r%f12, 0.0_wp, 0.0_wp], [2, 3]), [m1])
      r%residual = equilibrium_residual(links(1:1))
    else
      r%m2 = cross(r%p - r%o2, f21)
      r%m2_power = m1 * (-r%u)
      r%fs2 = -f21
      ! gear 2: mesh force, support, and the load's moment -M2
      links(1) = link_balance(reshape([o1, r%p, o1], [2, 3]), reshape([r%fs1, r%f12, 0.0_wp, 0.0_wp], [2, 3]), [m1])
      links(2) = link_balance(reshape([r%o2, r%p, r%o2], [2, 3]), reshape([r%fs2, f21, 0.0_wp, 0.0_wp], [2, 3]), &
                              [-r%m2])
      r%residual = equilibrium_residual(links)
    end if
    r%mismatch = power_mismatch(r%m2, r%m2_power, abs(r%m2_power))
  end function gear_pair

  !> Parallel-shaft stages in series (manual fig. 18 for two stages): gear 2 of stage i and
  !> gear 1 of stage i+1 share a shaft; M1 drives stage 1. The support of a shared shaft takes
  !> the resultant of both mesh forces; the output torque from the forces is checked against
  !> M_out = M1*prod(-u_i) (power balance, friction-free).
  pure subroutine gear_series(stages, m1, res)
    !> Stages (spur or helical), in order from the input.
    type(gear_stage_t), intent(in) :: stages(:)
    !> Input torque on gear 1 of stage 1, N*m.
    real(wp), intent(in) :: m1
    !> One result per stage; fs2 of stage i is the shared shaft's support resultant.
    type(gear_result_t), intent(out) :: res(size(stages))
    real(wp) :: o(2), m_in, m_power, f_on_shaft(2)
    integer :: i, n

    n = size(stages)
    o = 0.0_wp
    m_in = m1
    m_power = m1
    do i = 1, n
      res(i) = gear_pair(stages(i), m_in, o)
      m_power = m_power * (-res(i)%u)
      res(i)%m2_power = m_power
      res(i)%mismatch = power_mismatch(res(i)%m2, m_power, abs(m_power))
      o = res(i)%o2
      m_in = res(i)%m2
    end do
    ! shared shafts: driven gear of stage i (force -f12(i)) and driver of stage i+1 (f12(i+1))
    do i = 1, n - 1
      f_on_shaft = -res(i)%f12 + res(i + 1)%f12
      res(i)%fs2 = -f_on_shaft
      res(i + 1)%fs1 = -f_on_shaft
      res(i)%residual = max(res(i)%residual, &
        equilibrium_residual([link_balance(reshape([res(i)%p, res(i + 1)%p, res(i)%o2], [2, 3]), &
                      reshape([-res(i)%f12, res(i + 1)%f12, res(i)%fs2], [2, 3]), [real(wp) ::])]))
    end do
  end subroutine gear_series

  !> Single-row planetary gear (manual fig. 19): sun 1 driven by M1, k satellites 2 on the
  !> carrier H, fixed ring 3. Satellite j sits at angle gamma + 2*pi*(j-1)/k; the load is
  !> shared equally, F12 = 2*M1/(dw1*k*cos(alpha_w)). Satellite balance F21 + F23 + F2H = 0,
  !> carrier torque from the forces against M_H = M1*u_1H, u_1H = 1 + z3/z1 (same sense as
  !> M1), and the moment on the housing (ring) against M1 - M_H = -M1*z3/z1.
  pure function gear_planetary_step(st, m1) result(r)
    !> Stage geometry (kind gear_planetary; z3 = z1 + 2*z2).
    type(gear_stage_t), intent(in) :: st
    !> Torque on the sun from the input shaft, N*m.
    real(wp), intent(in) :: m1
    type(gear_result_t) :: r
    real(wp) :: r1, r2, a_w, e(2), m_sat, ft, fr12, fr23, p23(2), sum_sun(2)
    real(wp) :: m_carrier, m_ring, mis(2), f12j(2), f23j(2), f2hj(2), o2j(2), p12j(2)
    real(wp), allocatable :: sun_at(:, :), sun_f(:, :), car_at(:, :), car_f(:, :)
    !> Sun, carrier, satellites 1..k.
    type(link_balance_t), allocatable :: links(:)
    integer :: j

    r%m1 = m1
    r%u = 1.0_wp + real(st%z3, wp) / real(st%z1, wp)
    r%dw2 = st%dw1 * real(st%z2, wp) / real(st%z1, wp)
    r1 = 0.5_wp * st%dw1
    r2 = 0.5_wp * r%dw2
    a_w = r1 + r2
    m_sat = m1 / real(st%k, wp)
    ft = 2.0_wp * abs(m_sat) / st%dw1
    fr12 = ft * tan(st%alpha_w)
    fr23 = ft * tan(st%alpha_w23)
    r%ft = ft
    r%fr1 = fr12
    r%fr2 = fr12
    r%fa1 = 0.0_wp
    r%fa2 = 0.0_wp
    r%fn = ft / cos(st%alpha_w)

    allocate (sun_at(2, st%k + 1), sun_f(2, st%k + 1), car_at(2, st%k + 1), car_f(2, st%k + 1))
    allocate (links(st%k + 2))
    sum_sun = 0.0_wp
    m_carrier = 0.0_wp
    m_ring = 0.0_wp
    sun_at(:, 1) = 0.0_wp
    car_at(:, 1) = 0.0_wp
    do j = 1, st%k
      e = unit_at(st%gamma + 2.0_wp * pi * real(j - 1, wp) / real(st%k, wp))
      o2j = a_w * e
      p12j = r1 * e
      p23 = o2j + r2 * e
      f12j = driver_force(m_sat, r1, fr12, e)
      ! satellite moment balance about its pin: the ring's tangential force equals the sun's;
      ! the ring's radial force pushes the satellite towards the gear's axis
      f23j = (m_sat / r1) * perp(e) - fr23 * e
      f2hj = -(-f12j + f23j)
      sun_at(:, j + 1) = p12j
      sun_f(:, j + 1) = f12j
      car_at(:, j + 1) = o2j
      car_f(:, j + 1) = -f2hj
      sum_sun = sum_sun + f12j
      m_carrier = m_carrier + cross(o2j, -f2hj)
      m_ring = m_ring + cross(p23, -f23j)
      links(j + 2) = link_balance(reshape([o2j, p12j, p23], [2, 3]), reshape([f2hj, -f12j, f23j], [2, 3]), &
                                 [real(wp) ::])
      if (j == 1) then
        r%o2 = o2j
        r%p = p12j
        r%f12 = f12j
        r%f23 = f23j
        r%f2h = f2hj
      end if
    end do
    r%fs1 = -sum_sun
    r%fs2 = -sum(car_f(:, 2:), dim=2)
    sun_f(:, 1) = r%fs1
    car_f(:, 1) = r%fs2
    links(1) = link_balance(sun_at, sun_f, [m1])
    links(2) = link_balance(car_at, car_f, [-m_carrier])
    r%m2 = m_carrier
    r%m2_power = m1 * r%u
    r%m_house = m_ring
    r%m_house_power = m1 - r%m2_power
    r%residual = equilibrium_residual(links)
    mis(1) = power_mismatch(r%m2, r%m2_power, abs(r%m2_power))
    mis(2) = power_mismatch(r%m_house, r%m_house_power, abs(m1) + abs(r%m2_power))
    r%mismatch = maxval(mis)
  end function gear_planetary_step

end module kinetostat_gears
