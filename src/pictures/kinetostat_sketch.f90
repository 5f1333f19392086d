!> What a drawing of a mechanism needs beside the kinematics columns of the step table: the
!> topology, the same at every step. Which named points (the P of the x_<P>, y_<P> columns)
!> every link joins, which links are blocks sliding along a direction, the pivots and guides,
!> and the direction of gravity. Positions and link angles at a step come from the table
!> (x_<P>, y_<P>, phi<i>); a direction given "on link i" turns with phi<i>.
module kinetostat_sketch
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: sketch_t, sketch_link_t, sketch_guide_t, sketch_group_t

  !> Length of a point or link name.
  integer, parameter :: name_len = 16

  !> One moving link.
  type :: sketch_link_t
    !> Link number as in phi<i> ("3").
    character(len=:), allocatable :: name
    !> The points it joins (as in x_<P>), in drawing order: a bar through them.
    character(len=name_len), allocatable :: points(:)
    !> Whether it is a block (slider) drawn at points(1), sliding along `angle`.
    logical :: block = .false.
    !> Block: its sliding direction, deg: `angle` plus phi<along> (position frame when
    !> `along` is blank or the table has no phi<along>, e.g. a translating link).
    real(wp) :: angle = 0.0_wp
    !> Block: the link whose angle `angle` is measured from ("" for the position frame).
    character(len=:), allocatable :: along
  end type sketch_link_t

  !> A guide (a straight line along which a block slides).
  type :: sketch_guide_t
    !> A point of the line (as in x_<P>).
    character(len=name_len) :: point = ""
    !> Direction, deg: `angle` plus phi<on> (see sketch_link_t%angle).
    real(wp) :: angle = 0.0_wp
    !> The link carrying the guide ("" for the frame).
    character(len=:), allocatable :: on
  end type sketch_guide_t

  !> A unit of the structural analysis: an input unit or an Assur group.
  type :: sketch_group_t
    !> Its links (names as in phi<i>).
    character(len=name_len), allocatable :: links(:)
    !> Class: 1 an input unit (a drive in it), 2 a dyad, 3, 4 a group of that class.
    integer :: class = 0
    !> As the structure formula writes it ("II(2,3)").
    character(len=:), allocatable :: label
  end type sketch_group_t

  !> The topology of a mechanism (`available` false when the mechanism has none to draw).
  type :: sketch_t
    !> Whether the mechanism provides a sketch.
    logical :: available = .false.
    !> The moving links.
    type(sketch_link_t), allocatable :: links(:)
    !> Points fixed on the frame (revolute pairs with the frame).
    character(len=name_len), allocatable :: pivots(:)
    !> Guides of the prismatic pairs.
    type(sketch_guide_t), allocatable :: guides(:)
    !> Unit vector of gravity in the position frame.
    real(wp) :: down(2) = [0.0_wp, -1.0_wp]
    !> The structural analysis's units in the structure formula's order, when the mechanism
    !> has one (unallocated: the plans derive the groups from the topology).
    type(sketch_group_t), allocatable :: groups(:)
  contains
    procedure :: add_link
    procedure :: add_pivot
    procedure :: add_guide
    procedure :: add_group
  end type sketch_t

contains

  !> Append a link joining `points`; a block when `along` is present (sliding direction
  !> `angle` deg from the x axis of link `along`, "" for the position frame).
  pure subroutine add_link(self, name, points, angle, along)
    class(sketch_t), intent(inout) :: self
    !> Link number as in phi<i>.
    character(*), intent(in) :: name
    !> Points it joins (trailing blanks dropped).
    character(*), intent(in) :: points(:)
    !> Block: sliding direction, deg.
    real(wp), intent(in), optional :: angle
    !> Block: link the direction is measured from ("" for the position frame).
    character(*), intent(in), optional :: along
    type(sketch_link_t) :: link
    integer :: i
    link%name = name
    allocate (link%points(size(points)))
    do i = 1, size(points)
      link%points(i) = trim(points(i))
    end do
    link%along = ""
    if (present(along)) then
      link%block = .true.
      link%along = along
      if (present(angle)) link%angle = angle
    end if
    self%available = .true.
    if (.not. allocated(self%links)) allocate (self%links(0))
    self%links = [self%links, link]
  end subroutine add_link

  !> Append a pivot (a point fixed on the frame), once.
  pure subroutine add_pivot(self, point)
    class(sketch_t), intent(inout) :: self
    !> Point name.
    character(*), intent(in) :: point
    if (.not. allocated(self%pivots)) allocate (self%pivots(0))
    if (any(self%pivots == point)) return
    self%pivots = [character(len=name_len) :: self%pivots, point]
  end subroutine add_pivot

  !> Append a guide through `point` at `angle` deg from the x axis of link `on` ("" frame).
  pure subroutine add_guide(self, point, angle, on)
    class(sketch_t), intent(inout) :: self
    !> A point of the line.
    character(*), intent(in) :: point
    !> Direction, deg.
    real(wp), intent(in) :: angle
    !> Link carrying the guide ("" for the frame).
    character(*), intent(in) :: on
    if (.not. allocated(self%guides)) allocate (self%guides(0))
    self%guides = [self%guides, sketch_guide_t(point=point, angle=angle, on=on)]
  end subroutine add_guide

  !> Append a unit of the structure (links by name, class, label).
  pure subroutine add_group(self, links, class, label)
    class(sketch_t), intent(inout) :: self
    !> Its links' names.
    character(*), intent(in) :: links(:)
    !> Class (1: input unit).
    integer, intent(in) :: class
    !> As the structure formula writes it.
    character(*), intent(in) :: label
    type(sketch_group_t) :: group
    integer :: i
    allocate (group%links(size(links)))
    do i = 1, size(links)
      group%links(i) = trim(links(i))
    end do
    group%class = class
    group%label = label
    if (.not. allocated(self%groups)) allocate (self%groups(0))
    self%groups = [self%groups, group]
  end subroutine add_group

end module kinetostat_sketch
