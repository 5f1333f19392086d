!> Inertia (d'Alembert) and gravity loads of a link.
module kinetostat_loads
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: inertia_force, inertia_moment, gravity_force

contains

  !> Inertia force Phi = -m*a_S, N.
  pure function inertia_force(m, a_s) result(phi)
    !> Mass, kg.
    real(wp), intent(in) :: m
    !> Acceleration of the centre of mass, m/s^2.
    real(wp), intent(in) :: a_s(2)
    real(wp) :: phi(2)
    phi = -m * a_s
  end function inertia_force

  !> Inertia moment M_Phi = -J_S*eps, N*m.
  elemental function inertia_moment(j_s, eps) result(m_phi)
    !> Moment of inertia about the centre of mass, kg*m^2.
    real(wp), intent(in) :: j_s
    !> Angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps
    real(wp) :: m_phi
    m_phi = -j_s * eps
  end function inertia_moment

  !> Weight G = m*g along the unit direction `down` of the frame in use, N.
  pure function gravity_force(m, g, down) result(weight)
    !> Mass, kg.
    real(wp), intent(in) :: m
    !> Gravity, m/s^2.
    real(wp), intent(in) :: g
    !> Unit vector of gravity's direction in the frame used.
    real(wp), intent(in) :: down(2)
    real(wp) :: weight(2)
    weight = m * g * down
  end function gravity_force

end module kinetostat_loads
