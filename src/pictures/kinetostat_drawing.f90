!> The drawing of a mechanism at one step, for `--format svg --at K`: what a course-project
!> force-plan sheet shows, in a small vocabulary that kinetostat_svg_mechanism draws to scale.
!> - points (m, the mechanism's position frame): joints, frame pivots, centres of mass;
!> - bodies: a link as a bar (or plate) through named points, a slider as a block at a
!>   point, oriented along its sliding direction;
!> - guides: straight lines fixed on the frame (drawn hatched);
!> - forces (N, the position frame) applied at a point: pair forces, external loads,
!>   gravity, inertia forces; moments (N*m, counterclockwise positive) at a point.
!> `view_angle` turns the whole drawing on the sheet (so that gravity points down).
!> `drawing_from_sketch` builds the points, bodies and guides from the mechanism's topology
!> (kinetostat_sketch) and the kinematics columns of one row; the mechanism's `force_plan`
!> then adds the forces, with the helpers here that read pair forces (<F>_x, <F>_y with their
!> frame angle) and accelerations from the table.
module kinetostat_drawing
  use kinetostat_kinds, only: wp, pi, deg_to_rad
  use kinetostat_error, only: error_t, fatal_error, exit_usage
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_bodies, only: mass_model_t
  implicit none
  private
  public :: drawing_from_sketch, points_from_sketch
  public :: drawing_t, drawing_point_t, drawing_body_t, drawing_guide_t, drawing_force_t, drawing_moment_t
  public :: point_joint, point_pivot, point_com, point_plain, body_bar, body_block, body_cylinder, body_rod
  public :: force_pair, force_load, force_gravity, force_inertia, force_kind_names
  public :: column_value

  !> Point kind: a revolute joint between moving links.
  integer, parameter :: point_joint = 1
  !> Point kind: a revolute joint with the frame (drawn with the ground symbol).
  integer, parameter :: point_pivot = 2
  !> Point kind: a centre of mass.
  integer, parameter :: point_com = 3
  !> Point kind: a construction point (an end of a bar, a slider's reference point): not
  !> drawn, not named on the sheet.
  integer, parameter :: point_plain = 4
  !> Body kind: a bar (two points) or a plate (three or more) through its points.
  integer, parameter :: body_bar = 1
  !> Body kind: a slider block at one point, along `angle`.
  integer, parameter :: body_block = 2
  !> Body kind: a hydraulic cylinder: a tube from `anchor` along `angle`, `length` long.
  integer, parameter :: body_cylinder = 3
  !> Body kind: the rod of a cylinder: a bar on the axis through `anchor` along `angle`, from
  !> `reach(1)` to `reach(2)` (m from the anchor).
  integer, parameter :: body_rod = 4
  !> Force kind: a force in a kinematic pair.
  integer, parameter :: force_pair = 1
  !> Force kind: an external load (or the driving force).
  integer, parameter :: force_load = 2
  !> Force kind: a weight.
  integer, parameter :: force_gravity = 3
  !> Force kind: an inertia force (or the inertia moment).
  integer, parameter :: force_inertia = 4
  !> Names of the force kinds, for the legend.
  character(*), parameter :: force_kind_names(*) = [character(len=16) :: "pair force", "load", "weight", &
    "inertia"]

  !> A named point.
  type :: drawing_point_t
    !> Name ("B", "S3").
    character(len=16) :: name = ""
    !> Position, m.
    real(wp) :: p(2) = 0.0_wp
    !> point_joint, point_pivot or point_com.
    integer :: kind = point_joint
  end type drawing_point_t

  !> A link's body.
  type :: drawing_body_t
    !> Link name ("3").
    character(len=16) :: name = ""
    !> body_bar or body_block.
    integer :: kind = body_bar
    !> Indices of its points in drawing_t%points.
    integer, allocatable :: points(:)
    !> Block, cylinder, rod: sliding direction, rad (position frame).
    real(wp) :: angle = 0.0_wp
    !> Cylinder, rod: the point of the axis on the cylinder's pivot, m.
    real(wp) :: anchor(2) = 0.0_wp
    !> Cylinder: its length, m.
    real(wp) :: length = 0.0_wp
    !> Rod: its ends along the axis, m from the anchor.
    real(wp) :: reach(2) = 0.0_wp
  end type drawing_body_t

  !> A straight guide on the frame.
  type :: drawing_guide_t
    !> Its middle, m.
    real(wp) :: p(2) = 0.0_wp
    !> Direction, rad.
    real(wp) :: angle = 0.0_wp
    !> Half its length, m.
    real(wp) :: half_length = 0.0_wp
  end type drawing_guide_t

  !> A force at a point.
  type :: drawing_force_t
    !> Name ("F21", "G3", "Phi3").
    character(len=16) :: name = ""
    !> force_pair, force_load, force_gravity or force_inertia.
    integer :: kind = force_pair
    !> Point of application, m.
    real(wp) :: at(2) = 0.0_wp
    !> The force, N (position frame).
    real(wp) :: f(2) = 0.0_wp
    !> The link it acts on ("" when its name says: G3, Phi3, F21).
    character(len=16) :: on_link = ""
  end type drawing_force_t

  !> A moment at a point.
  type :: drawing_moment_t
    !> Name ("M1", "MPhi3").
    character(len=16) :: name = ""
    !> force_load (driving) or force_inertia.
    integer :: kind = force_load
    !> Where it is drawn, m.
    real(wp) :: at(2) = 0.0_wp
    !> Value, N*m, counterclockwise positive.
    real(wp) :: value = 0.0_wp
    !> The link it acts on ("" when its name says: MPhi3, M1).
    character(len=16) :: on_link = ""
  end type drawing_moment_t

  !> The whole sketch.
  type :: drawing_t
    !> Turn of the drawing on the sheet, rad (counterclockwise).
    real(wp) :: view_angle = 0.0_wp
    !> What the frame's turn means, for the caption ("gravity points down").
    character(len=:), allocatable :: view_note
    type(drawing_point_t), allocatable :: points(:)
    type(drawing_body_t), allocatable :: bodies(:)
    type(drawing_guide_t), allocatable :: guides(:)
    type(drawing_force_t), allocatable :: forces(:)
    type(drawing_moment_t), allocatable :: moments(:)
  contains
    procedure :: add_point
    procedure :: point_index
    procedure :: at
    procedure :: add_bar
    procedure :: add_block
    procedure :: add_guide
    procedure :: add_force
    procedure :: add_moment
    procedure :: point_from_table
    procedure :: pair_from_table
    procedure :: pairs_from_table
    procedure :: add_link_loads
    !> The weight and inertia loads of every moving link of a mass model.
    procedure :: add_body_loads
    procedure :: add_guide_over_rows
    procedure :: move_points_and_loads
  end type drawing_t

contains

  !> Add (or move) a point.
  pure subroutine add_point(self, name, p, kind)
    class(drawing_t), intent(inout) :: self
    !> Name.
    character(*), intent(in) :: name
    !> Position, m.
    real(wp), intent(in) :: p(2)
    !> point_* kind.
    integer, intent(in) :: kind
    type(drawing_point_t), allocatable :: grown(:)
    integer :: i
    if (.not. allocated(self%points)) allocate (self%points(0))
    i = self%point_index(name)
    if (i == 0) then
      allocate (grown(size(self%points) + 1))
      grown(1:size(self%points)) = self%points
      call move_alloc(grown, self%points)
      i = size(self%points)
    end if
    self%points(i)%name = name
    self%points(i)%p = p
    self%points(i)%kind = kind
  end subroutine add_point

  !> Index of the point called `name` (0 if none).
  pure integer function point_index(self, name)
    class(drawing_t), intent(in) :: self
    !> Name.
    character(*), intent(in) :: name
    integer :: i
    point_index = 0
    if (.not. allocated(self%points)) return
    do i = 1, size(self%points)
      if (self%points(i)%name == name) exit
    end do
    if (i <= size(self%points)) point_index = i
  end function point_index

  !> Position of the point called `name`, m ((0, 0) if there is none).
  pure function at(self, name) result(p)
    class(drawing_t), intent(in) :: self
    !> Name.
    character(*), intent(in) :: name
    real(wp) :: p(2)
    integer :: i
    p = 0.0_wp
    i = self%point_index(name)
    if (i > 0) p = self%points(i)%p
  end function at

  pure subroutine push_body(self, body)
    class(drawing_t), intent(inout) :: self
    type(drawing_body_t), intent(in) :: body
    if (.not. allocated(self%bodies)) allocate (self%bodies(0))
    self%bodies = [self%bodies, body]
  end subroutine push_body

  !> A link drawn as a bar (plate) through named points (unknown names are left out).
  pure subroutine add_bar(self, name, points)
    class(drawing_t), intent(inout) :: self
    !> Link name.
    character(*), intent(in) :: name
    !> Its points, in drawing order.
    character(*), intent(in) :: points(:)
    type(drawing_body_t) :: body
    integer :: i, j
    body%name = name
    body%kind = body_bar
    allocate (body%points(0))
    do i = 1, size(points)
      j = self%point_index(trim(points(i)))
      if (j > 0) body%points = [body%points, j]
    end do
    call push_body(self, body)
  end subroutine add_bar

  !> A slider block at a named point, sliding along `angle` (rad).
  pure subroutine add_block(self, name, point, angle)
    class(drawing_t), intent(inout) :: self
    !> Link name.
    character(*), intent(in) :: name
    !> Point name.
    character(*), intent(in) :: point
    !> Sliding direction, rad.
    real(wp), intent(in) :: angle
    type(drawing_body_t) :: body
    body%name = name
    body%kind = body_block
    body%points = [self%point_index(point)]
    body%angle = angle
    if (body%points(1) > 0) call push_body(self, body)
  end subroutine add_block

  !> A guide on the frame through `p` (m) along `angle` (rad), `half_length` (m) each way.
  pure subroutine add_guide(self, p, angle, half_length)
    class(drawing_t), intent(inout) :: self
    !> Middle, m.
    real(wp), intent(in) :: p(2)
    !> Direction, rad.
    real(wp), intent(in) :: angle
    !> Half length, m.
    real(wp), intent(in) :: half_length
    if (.not. allocated(self%guides)) allocate (self%guides(0))
    self%guides = [self%guides, drawing_guide_t(p, angle, half_length)]
  end subroutine add_guide

  !> A force `f` (N) of a kind, applied at `p` (m).
  pure subroutine add_force(self, name, kind, p, f, link)
    class(drawing_t), intent(inout) :: self
    !> Name.
    character(*), intent(in) :: name
    !> force_* kind.
    integer, intent(in) :: kind
    !> Point of application, m.
    real(wp), intent(in) :: p(2)
    !> Force, N.
    real(wp), intent(in) :: f(2)
    !> The link it acts on (for the plans; omitted when the name says it).
    character(*), intent(in), optional :: link
    if (.not. allocated(self%forces)) allocate (self%forces(0))
    self%forces = [self%forces, drawing_force_t(name, kind, p, f, given_link(link))]
  end subroutine add_force

  !> A moment (N*m, counterclockwise positive) of a kind at `p` (m).
  pure subroutine add_moment(self, name, kind, p, value, link)
    class(drawing_t), intent(inout) :: self
    !> Name.
    character(*), intent(in) :: name
    !> force_load or force_inertia.
    integer, intent(in) :: kind
    !> Where, m.
    real(wp), intent(in) :: p(2)
    !> Value, N*m.
    real(wp), intent(in) :: value
    !> The link it acts on (for the plans; omitted when the name says it).
    character(*), intent(in), optional :: link
    if (.not. allocated(self%moments)) allocate (self%moments(0))
    self%moments = [self%moments, drawing_moment_t(name, kind, p, value, given_link(link))]
  end subroutine add_moment

  !> The link a load acts on, "" when not given.
  pure function given_link(link) result(text)
    !> The link's name (optional).
    character(*), intent(in), optional :: link
    character(len=16) :: text
    text = ""
    if (present(link)) text = link
  end function given_link

  !> Point `name` of kind `kind` at the position the kinematics columns x_<name>, y_<name>
  !> of row `k` give; an error when the table has no such columns.
  pure subroutine point_from_table(self, table, k, name, kind, error)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> Point name.
    character(*), intent(in) :: name
    !> point_* kind.
    integer, intent(in) :: kind
    !> No position columns for this point.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: p(2)
    integer :: cx
    call column_pair(table, k, "x_"//name, "y_"//name, "position of point "//name, p, cx, error)
    if (allocated(error)) return
    call self%add_point(name, p, kind)
  end subroutine point_from_table

  !> The values of columns `x_name` and `y_name` at row `k` (and the first column's index);
  !> an error naming `what` when the table has no such columns.
  pure subroutine column_pair(table, k, x_name, y_name, what, v, cx, error)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> Column names.
    character(*), intent(in) :: x_name, y_name
    !> What the two columns give ("position of point B"), for the message.
    character(*), intent(in) :: what
    !> The two values.
    real(wp), intent(out) :: v(2)
    !> Index of column `x_name`.
    integer, intent(out) :: cx
    !> No such columns.
    type(error_t), allocatable, intent(out) :: error
    integer :: cy
    v = 0.0_wp
    cx = table%column_index(x_name)
    cy = table%column_index(y_name)
    if (cx == 0 .or. cy == 0) then
      call fatal_error(error, exit_usage, table%deck//": &"//table%mechanism//": --at: no "//what// &
        " in the results ("//x_name//", "//y_name//")")
      return
    end if
    v = [table%rows(cx, k), table%rows(cy, k)]
  end subroutine column_pair

  !> Pair force `name` at the point called `point`, from the component columns <name>_x,
  !> <name>_y of row `k`, turned from their frame (the column's frame_angle) into the
  !> position frame; an error when the table has no such columns.
  pure subroutine pair_from_table(self, table, k, name, point, error)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> Force name ("F21").
    character(*), intent(in) :: name
    !> Point of application (a point added before).
    character(*), intent(in) :: point
    !> No component columns for this force.
    type(error_t), allocatable, intent(out) :: error
    integer :: cx
    real(wp) :: f(2), a
    call column_pair(table, k, name//"_x", name//"_y", "components of "//name, f, cx, error)
    if (allocated(error)) return
    a = table%columns(cx)%frame_angle * deg_to_rad
    call self%add_force(name, force_pair, self%at(point), [cos(a) * f(1) - sin(a) * f(2), sin(a) * f(1) + cos(a) * f(2)])
  end subroutine pair_from_table

  !> Every pair force names(i) at its point points(i), from row `k` (see pair_from_table).
  pure subroutine pairs_from_table(self, table, k, names, points, error)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> Force names ("F21"; trailing blanks dropped).
    character(*), intent(in) :: names(:)
    !> Their points of application (points added before; trailing blanks dropped).
    character(*), intent(in) :: points(:)
    !> No component columns for a force.
    type(error_t), allocatable, intent(out) :: error
    integer :: i
    do i = 1, size(names)
      call self%pair_from_table(table, k, trim(names(i)), trim(points(i)), error)
      if (allocated(error)) return
    end do
  end subroutine pairs_from_table

  !> The weight, inertia force and inertia moment of every moving link of the mass model at
  !> row `k`, each at its centre of mass (see add_link_loads).
  pure subroutine add_body_loads(self, table, k, model)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> The mechanism's moving links and gravity.
    type(mass_model_t), intent(in) :: model
    integer :: i
    if (.not. model%available) return
    do i = 1, size(model%bodies)
      associate (b => model%bodies(i))
        call self%add_link_loads(table, k, b%link, b%centre, b%centre, b%mass, b%inertia, model%gravity)
      end associate
    end do
  end subroutine add_body_loads

  !> The loads of a moving link at row `k`: its weight G<link> = mass * gravity and inertia
  !> force Phi<link> = -mass * a (from the columns ax_<com>, ay_<com>), both at the point
  !> `at`, and its inertia moment MPhi<link> = -inertia * eps<link> (column eps<link>).
  !> Zero masses and moments of inertia add nothing; missing columns count as zero.
  pure subroutine add_link_loads(self, table, k, link, at, com, mass, inertia, gravity)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> Link name ("3").
    character(*), intent(in) :: link
    !> Point where the loads are drawn (the centre of mass, or the point it coincides with).
    character(*), intent(in) :: at
    !> Name of the centre of mass in the acceleration columns ("S3").
    character(*), intent(in) :: com
    !> Mass, kg.
    real(wp), intent(in) :: mass
    !> Moment of inertia about the centre of mass, kg*m^2.
    real(wp), intent(in) :: inertia
    !> Gravity vector, m/s^2 (position frame).
    real(wp), intent(in) :: gravity(2)
    real(wp) :: a(2), eps
    if (mass > 0.0_wp) then
      if (any(gravity /= 0.0_wp)) call self%add_force("G"//link, force_gravity, self%at(at), mass * gravity, link)
      a = [column_value(table, "ax_"//com, k), column_value(table, "ay_"//com, k)]
      if (any(a /= 0.0_wp)) call self%add_force("Phi"//link, force_inertia, self%at(at), -mass * a, link)
    end if
    eps = column_value(table, "eps"//link, k)
    if (inertia > 0.0_wp .and. eps /= 0.0_wp) then
      call self%add_moment("MPhi"//link, force_inertia, self%at(at), -inertia * eps, link)
    end if
  end subroutine add_link_loads

  !> A guide on the frame along `angle` (rad) through the positions point `name` takes over
  !> all rows of the table (x_<name>, y_<name>), `margin` (m) longer at each end: the travel
  !> of a slider, whatever the row drawn.
  pure subroutine add_guide_over_rows(self, table, name, angle, margin)
    class(drawing_t), intent(inout) :: self
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Point name.
    character(*), intent(in) :: name
    !> Direction, rad.
    real(wp), intent(in) :: angle
    !> Extra length at each end, m.
    real(wp), intent(in) :: margin
    real(wp), allocatable :: s(:)
    real(wp) :: u(2), p0(2)
    integer :: cx, cy
    cx = table%column_index("x_"//name)
    cy = table%column_index("y_"//name)
    if (cx == 0 .or. cy == 0 .or. table%row_count() == 0) return
    allocate (s(0)) ! defined before the assignment (gcc's -Wmaybe-uninitialized on the descriptor)
    u = [cos(angle), sin(angle)]
    s = u(1) * table%rows(cx, :) + u(2) * table%rows(cy, :)
    p0 = [table%rows(cx, 1), table%rows(cy, 1)]
    p0 = p0 + (0.5_wp * (minval(s) + maxval(s)) - dot_product(u, p0)) * u
    call self%add_guide(p0, angle, 0.5_wp * (maxval(s) - minval(s)) + margin)
  end subroutine add_guide_over_rows

  !> Moves the drawing's points and the points of application of its forces and moments by
  !> `by` (its bodies and guides stay: a drawing taken apart to be moved has none that it
  !> draws from their own coordinates).
  pure subroutine move_points_and_loads(self, by)
    class(drawing_t), intent(inout) :: self
    !> The move, m.
    real(wp), intent(in) :: by(2)
    integer :: j
    do j = 1, size(self%forces)
      self%forces(j)%at = self%forces(j)%at + by
    end do
    do j = 1, size(self%moments)
      self%moments(j)%at = self%moments(j)%at + by
    end do
    do j = 1, size(self%points)
      self%points(j)%p = self%points(j)%p + by
    end do
  end subroutine move_points_and_loads

  !> The named points of row `k` from the mechanism's topology (the first part of
  !> drawing_from_sketch, without bodies and guides): every point a link or pivot names
  !> (x_<P>, y_<P>), the centre of mass S<i> of every link i the table has; the view turned so
  !> that `topo%down` points down.
  pure subroutine points_from_sketch(topo, table, k, drawing, error)
    !> The mechanism's topology (available).
    type(sketch_t), intent(in) :: topo
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> The drawing: its points.
    type(drawing_t), intent(out) :: drawing
    !> A named point without position columns.
    type(error_t), allocatable, intent(out) :: error
    integer :: i, j, kind
    drawing%view_angle = -0.5_wp * pi - atan2(topo%down(2), topo%down(1))
    drawing%view_note = "gravity down the sheet"
    ! every list allocated (empty): the writers loop over them without asking
    allocate (drawing%points(0), drawing%bodies(0), drawing%guides(0), drawing%forces(0), drawing%moments(0))
    if (allocated(topo%links)) then
      do i = 1, size(topo%links)
        do j = 1, size(topo%links(i)%points)
          kind = point_joint
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == topo%links(i)%points(j))) kind = point_pivot
          end if
          call drawing%point_from_table(table, k, trim(topo%links(i)%points(j)), kind, error)
          if (allocated(error)) return
        end do
      end do
      do i = 1, size(topo%links)
        if (table%column_index("x_S"//topo%links(i)%name) > 0 .and. &
          drawing%point_index("S"//topo%links(i)%name) == 0) then
          call drawing%point_from_table(table, k, "S"//topo%links(i)%name, point_com, error)
          if (allocated(error)) return
        end if
      end do
    end if
    if (allocated(topo%pivots)) then
      do i = 1, size(topo%pivots)
        call drawing%point_from_table(table, k, trim(topo%pivots(i)), point_pivot, error)
        if (allocated(error)) return
      end do
    end if
  end subroutine points_from_sketch

  !> The points, bodies and guides of row `k` from the mechanism's topology `topo` and the
  !> kinematics columns: every point a link, pivot or guide names (x_<P>, y_<P>; pivots with
  !> the ground symbol), the centre of mass S<i> of every link i the table has; links as bars
  !> through their points, blocks at their point along angle + phi<along>; guides on the
  !> frame over the travel of their point (guides on a moving link are its bar); the sheet
  !> turned so that `topo%down` points down.
  pure subroutine drawing_from_sketch(topo, table, k, drawing, error)
    !> The mechanism's topology (available).
    type(sketch_t), intent(in) :: topo
    !> The results with their kinematics columns.
    type(step_table_t), intent(in) :: table
    !> Row.
    integer, intent(in) :: k
    !> The drawing (without forces).
    type(drawing_t), intent(out) :: drawing
    !> A named point without position columns.
    type(error_t), allocatable, intent(out) :: error
    integer :: i
    real(wp) :: angle, size_scale, lo(2), hi(2)
    character(len=:), allocatable :: along
    call points_from_sketch(topo, table, k, drawing, error)
    if (allocated(error)) return
    lo = huge(1.0_wp)
    hi = -huge(1.0_wp)
    do i = 1, size(drawing%points)
      lo = min(lo, drawing%points(i)%p)
      hi = max(hi, drawing%points(i)%p)
    end do
    size_scale = max(hi(1) - lo(1), hi(2) - lo(2))
    if (allocated(topo%links)) then
      do i = 1, size(topo%links)
        associate (l => topo%links(i))
          if (l%block) then
            along = ""
            if (allocated(l%along)) along = l%along
            angle = l%angle * deg_to_rad
            if (len(along) > 0) angle = angle + column_value(table, "phi"//along, k) * deg_to_rad
            call drawing%add_block(l%name, trim(l%points(1)), angle)
            if (size(l%points) > 1) call drawing%add_bar(l%name, body_points(l%points, l%name))
          else
            call drawing%add_bar(l%name, body_points(l%points, l%name))
          end if
        end associate
      end do
    end if
    if (allocated(topo%guides)) then
      do i = 1, size(topo%guides)
        associate (g => topo%guides(i))
          if (allocated(g%on)) then
            if (len(g%on) > 0) cycle
          end if
          call drawing%add_guide_over_rows(table, trim(g%point), g%angle * deg_to_rad, 0.08_wp * size_scale)
        end associate
      end do
      call find_cylinders(topo, table, k, size_scale, drawing)
    end if
  contains
    !> The points a link's body reaches: its own, and its centre of mass S<link> when the
    !> drawing shows it (a body must reach every point of it the sheet shows).
    pure function body_points(points, link) result(all)
      character(*), intent(in) :: points(:), link
      character(len=16), allocatable :: all(:)
      all = [character(len=16) :: points]
      if (drawing%point_index("S"//link) > 0 .and. .not. any(all == "S"//link)) all = [character(len=16) :: all, "S"//link]
    end function body_points
  end subroutine drawing_from_sketch

  !> A guide on a moving link G through a point only G lists (its pivot) is a cylinder's axis:
  !> G is drawn as the tube (twice as long as from the pivot to its centre of mass), the
  !> link that slides along that axis (a point on it, turning with G) as its rod, from inside
  !> the tube to its farthest point.
  pure subroutine find_cylinders(topo, table, k, size_scale, drawing)
    type(sketch_t), intent(in) :: topo
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    !> Size of the mechanism, m.
    real(wp), intent(in) :: size_scale
    type(drawing_t), intent(inout) :: drawing
    integer :: gi, li, ri, bi, j, q
    real(wp) :: u(2), p0(2), t, tube, far, angle
    do gi = 1, size(topo%guides)
      associate (g => topo%guides(gi))
        if (.not. allocated(g%on)) cycle
        if (len(g%on) == 0) cycle
        li = 0
        do j = 1, size(topo%links)
          if (topo%links(j)%name == g%on) li = j
        end do
        if (li == 0) cycle
        if (any([(j /= li .and. any(topo%links(j)%points == g%point), j=1, size(topo%links))])) cycle
        if (drawing%point_index(trim(g%point)) == 0) cycle
        p0 = drawing%at(trim(g%point))
        angle = (g%angle + column_value(table, "phi"//g%on, k)) * deg_to_rad
        u = [cos(angle), sin(angle)]
        ! the rod: another link with a point on the axis (not the anchor)
        ri = 0
        far = 0.0_wp
        do j = 1, size(topo%links)
          if (j == li) cycle
          do q = 1, size(topo%links(j)%points)
            if (drawing%point_index(trim(topo%links(j)%points(q))) == 0) cycle
            associate (x => drawing%at(trim(topo%links(j)%points(q))) - p0)
              if (abs(x(1) * u(2) - x(2) * u(1)) <= 1.0e-6_wp * (size_scale + norm2(x)) .and. &
                norm2(x) > 1.0e-9_wp * size_scale) then
                ri = j
                far = dot_product(x, u)
              end if
            end associate
          end do
          if (ri > 0) exit
        end do
        if (ri == 0) cycle
        if (far < 0.0_wp) then
          u = -u
          angle = angle + pi
          far = -far
        end if
        tube = 0.0_wp
        do q = 1, size(topo%links(li)%points)
          t = dot_product(drawing%at(trim(topo%links(li)%points(q))) - p0, u)
          tube = max(tube, 2.0_wp * t)
        end do
        if (drawing%point_index("S"//g%on) > 0) tube = max(tube, 2.0_wp * dot_product(drawing%at("S"//g%on) - p0, u))
        if (tube <= 0.0_wp .or. tube >= far) tube = 0.6_wp * far
        do bi = 1, size(drawing%bodies)
          if (drawing%bodies(bi)%kind /= body_bar) cycle
          if (drawing%bodies(bi)%name == g%on) then
            drawing%bodies(bi)%kind = body_cylinder
            drawing%bodies(bi)%angle = angle
            drawing%bodies(bi)%anchor = p0
            drawing%bodies(bi)%length = tube
          else if (drawing%bodies(bi)%name == topo%links(ri)%name) then
            drawing%bodies(bi)%kind = body_rod
            drawing%bodies(bi)%angle = angle
            drawing%bodies(bi)%anchor = p0
            drawing%bodies(bi)%reach = [0.5_wp * tube, far]
            do q = 1, size(topo%links(ri)%points)
              if (drawing%point_index(trim(topo%links(ri)%points(q))) == 0) cycle
              drawing%bodies(bi)%reach(2) = max(drawing%bodies(bi)%reach(2), &
                dot_product(drawing%at(trim(topo%links(ri)%points(q))) - p0, u))
            end do
          end if
        end do
      end associate
    end do
  end subroutine find_cylinders

  !> Value of column `name` at row `k` (0 when the table has no such column).
  pure real(wp) function column_value(table, name, k)
    type(step_table_t), intent(in) :: table
    character(*), intent(in) :: name
    integer, intent(in) :: k
    integer :: c
    column_value = 0.0_wp
    c = table%column_index(name)
    if (c > 0) column_value = table%rows(c, k)
  end function column_value

end module kinetostat_drawing
