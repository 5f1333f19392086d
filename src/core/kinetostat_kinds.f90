!> Kinds and physical/mathematical constants shared by every layer.
module kinetostat_kinds
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none
  private
  public :: wp, pi, deg_to_rad, rad_to_deg, g_default, version_string

  !> Working precision: IEEE double.
  integer, parameter :: wp = real64
  !> pi, dimensionless.
  real(wp), parameter :: pi = 3.141592653589793238462643383279502884_wp
  !> Degrees to radians factor, rad/deg.
  real(wp), parameter :: deg_to_rad = pi / 180.0_wp
  !> Radians to degrees factor, deg/rad.
  real(wp), parameter :: rad_to_deg = 180.0_wp / pi
  !> Standard gravity used when a deck gives no `g`, m/s^2.
  real(wp), parameter :: g_default = 9.81_wp
  !> Program version printed by `--version`.
  character(*), parameter :: version_string = "kinetostat 0.1.0"
end module kinetostat_kinds
