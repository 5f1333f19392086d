!> The mass model of a linkage mechanism: every moving link's mass, moment of inertia and
!> centre of mass, named as in the step table's kinematics columns, and the gravity vector.
!> The stages that sum over the links (drawing the weights and inertia loads, reduced
!> inertia, shaking force and moment) read it from `mechanism_t%mass_model` instead of each
!> mechanism listing its links again.
module kinetostat_bodies
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: body_t, mass_model_t, frame_pair_t

  !> One moving link.
  type :: body_t
    !> Link name as in the columns phi<link>, omega<link>, eps<link> ("3"); a link that only
    !> translates has no such columns (their values read as 0).
    character(len=:), allocatable :: link
    !> Its centre of mass as in the columns x_<centre>, y_<centre>, ax_<centre>, ay_<centre> ("S3").
    character(len=:), allocatable :: centre
    !> Mass, kg.
    real(wp) :: mass = 0.0_wp
    !> Moment of inertia about the centre of mass, kg*m^2.
    real(wp) :: inertia = 0.0_wp
  end type body_t

  !> A pair of a moving link with the frame: the force the frame exerts on the link, where it
  !> acts and the pair's reaction moment (the frame takes the opposite of both).
  type :: frame_pair_t
    !> Force name as in the component columns <force>_x, <force>_y ("F16"): the force on the
    !> moving link from the frame.
    character(len=:), allocatable :: force
    !> Point it acts at, as in the columns x_<point>, y_<point> ("A"); "" when the table does
    !> not give its line of action (the frame's moment is then not reported).
    character(len=:), allocatable :: point
    !> Column of the pair's reaction moment on the link about that point (a prismatic pair's
    !> "F30M"); "" when the pair transmits none.
    character(len=:), allocatable :: moment
  end type frame_pair_t

  !> The moving links of a mechanism and the gravity acting on them.
  type :: mass_model_t
    !> Whether the mechanism has one (linkages do; gears and cams do not).
    logical :: available = .false.
    !> The moving links, in the mechanism's link order.
    type(body_t), allocatable :: bodies(:)
    !> Gravity vector in the frame of the kinematics columns, m/s^2.
    real(wp) :: gravity(2) = 0.0_wp
    !> The pairs with the frame (for the total force and moment on the frame); none listed:
    !> the frame's total is not reported.
    type(frame_pair_t), allocatable :: frame_pairs(:)
    !> Column of the driving moment on the crank ("M1"), whose reaction acts on the motor's
    !> housing on the frame; "" when the drive is internal (an actuator between two links).
    character(len=:), allocatable :: drive
  contains
    !> Append a link.
    procedure :: add
    !> Append a pair with the frame.
    procedure :: add_frame_pair
  end type mass_model_t

contains

  !> Append a moving link to the model (and mark the model available).
  pure subroutine add(self, link, centre, mass, inertia)
    class(mass_model_t), intent(inout) :: self
    !> Link name ("3").
    character(*), intent(in) :: link
    !> Centre of mass ("S3").
    character(*), intent(in) :: centre
    !> Mass, kg.
    real(wp), intent(in) :: mass
    !> Moment of inertia about the centre of mass, kg*m^2.
    real(wp), intent(in) :: inertia
    if (.not. allocated(self%bodies)) allocate (self%bodies(0))
    self%bodies = [self%bodies, body_t(link, centre, mass, inertia)]
    self%available = .true.
  end subroutine add

  !> Append a pair with the frame (see frame_pair_t).
  pure subroutine add_frame_pair(self, force, point, moment)
    class(mass_model_t), intent(inout) :: self
    !> Force name ("F16"): columns <force>_x, <force>_y, the force on the link from the frame.
    character(*), intent(in) :: force
    !> Point of action ("A"; "" when unknown).
    character(*), intent(in) :: point
    !> Column of the pair's reaction moment about the point ("" for none).
    character(*), intent(in) :: moment
    if (.not. allocated(self%frame_pairs)) allocate (self%frame_pairs(0))
    self%frame_pairs = [self%frame_pairs, frame_pair_t(force, point, moment)]
  end subroutine add_frame_pair

end module kinetostat_bodies
