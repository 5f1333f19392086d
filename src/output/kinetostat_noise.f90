!> Roundoff floors of the output, shared by every mechanism: a force at or below
!> `noise_rel` times the largest force of its step vanishes in theory and is reported as 0
!> with angle 0; magnitude and angle columns of forces.
module kinetostat_noise
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: magnitude, largest_magnitude, snap_noise, angle_360_deg, angle_180_deg
  implicit none
  private
  public :: noise_rel, angles_0_360, angles_pm180, noise_floor, force_columns, force_components

  !> Relative roundoff floor: a force at or below noise_rel times the largest force of its
  !> step vanishes in theory and is printed as 0 with angle 0.
  real(wp), parameter :: noise_rel = 1.0e-12_wp
  !> Force angles in [0, 360).
  integer, parameter :: angles_0_360 = 1
  !> Force angles in (-180, 180], as ATAN2 gives them.
  integer, parameter :: angles_pm180 = 2

contains

  !> Roundoff floor of one step: noise_rel times the largest of the force magnitudes
  !> (columns of f) and of the absolute values of `others` (signed forces), N.
  pure function noise_floor(f, others) result(floor)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Further signed forces of the step, N (may be empty).
    real(wp), intent(in) :: others(:)
    real(wp) :: floor
    floor = largest_magnitude(f)
    if (size(others) > 0) floor = max(floor, maxval(abs(others)))
    floor = noise_rel * floor
  end function noise_floor

  !> Magnitude and angle (deg) columns of forces: [|f1|, angle1, |f2|, angle2, ...];
  !> a force at or below `floor` is roundoff and gives 0, 0. Without `angles` (a run whose
  !> outputs show no angle: step_table_t's force_angles_wanted) the angle cells are 0.
  pure function force_columns(f, floor, angle_range, angles) result(v)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Roundoff floor, N (see noise_floor).
    real(wp), intent(in) :: floor
    !> angles_0_360 or angles_pm180.
    integer, intent(in) :: angle_range
    !> Whether the angles are computed (default true).
    logical, intent(in), optional :: angles
    real(wp) :: v(2 * size(f, 2))
    real(wp) :: fi(2)
    integer :: i
    do i = 1, size(f, 2)
      fi = snap_noise(f(:, i), floor)
      v(2 * i - 1) = magnitude(fi)
      if (present(angles)) then
        if (.not. angles) then
          v(2 * i) = 0.0_wp
          cycle
        end if
      end if
      if (angle_range == angles_pm180) then
        v(2 * i) = angle_180_deg(fi)
      else
        v(2 * i) = angle_360_deg(fi)
      end if
    end do
  end function force_columns

  !> The x, y components of a force as the kinematics columns report it: a force at or below
  !> `floor` is 0 (as its magnitude and angle columns), and so is a single component at or
  !> below it (a force along an axis has exactly one nonzero component).
  pure function force_components(f, floor) result(v)
    !> Force, N.
    real(wp), intent(in) :: f(2)
    !> Roundoff floor, N (see noise_floor).
    real(wp), intent(in) :: floor
    real(wp) :: v(2)
    v = snap_noise(f, floor)
    where (abs(v) <= floor) v = 0.0_wp
  end function force_components

end module kinetostat_noise
