!> The graphical method's plans at one step: the types every part of it shares (the plans of
!> velocities and accelerations, the groups, the force polygons, Zhukovsky's lever, the values
!> table) and the questions they all ask of the mechanism's topology (kinetostat_sketch) and
!> of one step's drawing (kinetostat_drawing): which link a point or a load belongs to, which
!> links slide on which guide, the velocity field of a link.
module kinetostat_plans_base
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_pair, column_value
  implicit none
  private
  public :: plans_t, plan_vector_t, plan_equation_t, plan_group_t, force_polygon_t, plan_reaction_t, slide_t
  public :: lever_load_t, lever_friction_t, plan_value_t
  public :: component_normal, component_tangential, component_coriolis, component_relative, component_reaction
  public :: load_force, load_moment
  public :: field, cross, perp, link_index, lists, sliding_on, guide_link, slides_of, slide_is_pair, driver_links
  public :: owner, image_of, closure_of, coincident, pivot_of, point_velocity

  !> A named vector (a point's image on a plan, a force of a polygon).
  type :: plan_vector_t
    !> Name ("B", "G2", "F21", "a_CB^τ": up to two joint names of 16 bytes each and a
    !> component's marks, so no name is cut).
    character(len=48) :: name = ""
    !> Components (position frame): m/s, m/s^2 or N.
    real(wp) :: v(2) = 0.0_wp
    !> A component's kind (component_normal ... on the acceleration plan, a reaction's part in
    !> a force polygon; "" otherwise).
    character(len=1) :: kind = ""
  end type plan_vector_t

  !> Kinds of the acceleration components: normal (centripetal, omega^2 l toward the centre),
  !> tangential (eps x l), Coriolis (2 omega x v_rel), relative (sliding, along the guide).
  character(len=1), parameter :: component_normal = "n", component_tangential = "t", &
    component_coriolis = "k", component_relative = "r"
  !> Kind of a whole (unsplit) unknown reaction in a group's force polygon.
  character(len=1), parameter :: component_reaction = "f"
  !> Kinds of a load on Zhukovsky's lever.
  character(*), parameter :: load_force = "force", load_moment = "moment"

  !> One vector equation of a plan, as the graphical method adds it: the image of `point` =
  !> the image of `from` (the pole when blank) + the components in order.
  type :: plan_equation_t
    !> The point whose image the equation gives ("B").
    character(len=16) :: point = ""
    !> The link whose omega and eps the normal and tangential components use ("2").
    character(len=16) :: link = ""
    !> The known point the chain starts from ("A"; blank: the pole).
    character(len=16) :: from = ""
    !> A slider's equation: the sliding link (the relative components are its motion
    !> along the guide of `link`, or of the frame when `link` is blank); blank otherwise.
    character(len=16) :: slider = ""
    !> The components in drawing order, m/s or m/s^2.
    type(plan_vector_t), allocatable :: vectors(:)
    !> A slider's equation the other way round: `point` is a point of the guide's link
    !> `link`, `from` the slider's point; the Coriolis term is the guide's point's relative
    !> to the slider, 2 omega_slider x (v_link - v_slider) at `from`.
    logical :: reverse = .false.
  end type plan_equation_t

  !> A unit of the structure: an input unit (a drive in it) or an Assur group; its links
  !> (indices in the topology), in the order the structural analysis lists them.
  type :: plan_group_t
    integer, allocatable :: links(:)
    !> Their names ("2", "3").
    character(len=16), allocatable :: names(:)
    !> Whether it is an input unit (class I: the drive's link, or a group with its drive).
    logical :: input = .false.
    !> Class (1 input unit, 2 dyad, 3, 4; 0 not classified).
    integer :: class = 0
    !> As the structure formula writes it ("II(2,3)", "I(0,1)").
    character(len=:), allocatable :: label
    !> An input unit's drive effort ("M1", "M4", "F2"; "" for none known).
    character(len=:), allocatable :: drive
  end type plan_group_t

  !> A slider: link m moves along u (a unit vector) relative to link g (0: the frame) at the
  !> point p of m, called `name`.
  type :: slide_t
    integer :: m = 0, g = 0
    real(wp) :: p(2) = 0.0_wp, u(2) = 0.0_wp
    character(len=16) :: name = ""
    !> The guide's direction, deg: on link g (from its phi<g>; in the position frame when g =
    !> 0), and whether it is a block's (u from (angle + phi<g>), else from angle and phi<g>
    !> turned to radians apart).
    real(wp) :: angle = 0.0_wp
    logical :: block = .false.
  end type slide_t

  !> A whole reaction a group's force polygon gives: an outer reaction (its parts drawn, the
  !> whole from the first part's tail to the last part's head) or an inner one (found from
  !> one link's polygon, drawn between two vertices of the group's polygon).
  type :: plan_reaction_t
    !> Name F<on><from> ("F21": on link 2 from link 1).
    character(len=16) :: name = ""
    !> The reaction, N (position frame).
    real(wp) :: v(2) = 0.0_wp
    !> Whether it acts between two links of the group.
    logical :: inner = .false.
    !> The polygon's vertices it is drawn between (0 .. n: vertex j follows the first j
    !> vectors; vertex n is vertex 0).
    integer :: tail = 0, head = 0
  end type plan_reaction_t

  !> A force polygon: of one link, or of a unit of the structure.
  type :: force_polygon_t
    !> Link name, or the group's links ("2,3").
    character(len=16) :: link = ""
    !> The unit as the structure formula writes it ("II(2,3)"; "" for a link's polygon).
    character(len=:), allocatable :: label
    !> Whether the unit is an input unit.
    logical :: input = .false.
    !> The vectors in drawing order.
    type(plan_vector_t), allocatable :: vectors(:)
    !> |sum of the vectors| / largest vector (0 for a closed polygon).
    real(wp) :: closure = 0.0_wp
    !> An input unit's polygon: the drive's moment (or force) name ("" for none) and value.
    character(len=:), allocatable :: moment
    real(wp) :: moment_value = 0.0_wp
    !> The whole reactions the polygon gives (outer, then inner).
    type(plan_reaction_t), allocatable :: reactions(:)
  end type force_polygon_t

  !> A load on Zhukovsky's lever: a force at the velocity image of its point, or a moment as
  !> its couple of forces F = M / l at the images of two points of its link, l apart.
  type :: lever_load_t
    !> Name as the drawing writes it ("G2", "Phi2", "MPhi3", "M4", "M_fw", "Mf21", "P_bal").
    character(len=16) :: name = ""
    !> load_force or load_moment.
    character(len=6) :: kind = load_force
    !> A force: its magnitude, N; a moment: its value, N*m (counterclockwise positive).
    real(wp) :: value = 0.0_wp
    !> A force: the force, N (position frame); a moment: the couple's force at `points(1)`
    !> (the other, reversed, at `points(2)`).
    real(wp) :: f(2) = 0.0_wp
    !> The points (drawing names; a force: one, a moment or a pair of actions: two) and their
    !> velocity images, m/s (position frame).
    character(len=16) :: points(2) = ""
    real(wp) :: at(2) = 0.0_wp, at2(2) = 0.0_wp
    !> Names of the images as the plan writes them ("s2"; "b,c").
    character(len=32) :: image = ""
    !> Whether it is a pair of opposite forces (a couple, or the actions of a pair on its two
    !> links) rather than one force.
    logical :: pair = .false.
    !> A couple: the distance of its two points, m.
    real(wp) :: l = 0.0_wp
    !> Arm on the lever (from the pole to the force's line; a pair: between its two lines),
    !> m/s at the plan's units.
    real(wp) :: arm = 0.0_wp
    !> Power (the lever's moment about the pole with the sign reversed), W.
    real(wp) :: power = 0.0_wp
    !> The drawing's force kind it comes from (force_gravity ...; 0 for friction and the flywheel).
    integer :: source = 0
    !> The link it acts on (a pair of actions: the first).
    character(len=16) :: link = ""
  end type lever_load_t

  !> The friction of one pair on Zhukovsky's lever: equal and opposite actions on the pair's
  !> two links, opposing their relative motion - at a revolute pair a couple (moment on `on`,
  !> -moment on `from`), at a prismatic pair a force along the relative sliding (force on
  !> `on` at `at`, -force on `from` at the same point).
  type :: lever_friction_t
    !> The pair's reaction name ("F21": on link 2 from link 1).
    character(len=16) :: pair = ""
    !> The two links ("2", "1"; the frame's number for the frame).
    character(len=16) :: on = "", from = ""
    !> Whether the pair is prismatic (the table has its normal force <pair>N).
    logical :: prismatic = .false.
    !> Revolute pair: the friction couple on `on`, N*m (counterclockwise positive).
    real(wp) :: moment = 0.0_wp
    !> Prismatic pair: the friction force on `on`, N (position frame), and its point, m.
    real(wp) :: force(2) = 0.0_wp, at(2) = 0.0_wp
    !> Relative motion from the plan: omega_on - omega_from (rad/s, first component) at a
    !> revolute pair; v_on - v_from at `at` (m/s) at a prismatic one.
    real(wp) :: relative(2) = 0.0_wp
    !> Power of the two actions on the lever, W (minus the pair's loss).
    real(wp) :: power = 0.0_wp
  end type lever_friction_t

  !> One line of the values table beside the plans: a quantity read off a plan (or computed
  !> from one) as the student writes it, "omega2 = v_CB / l_CB = 22.7 rad/s, ccw".
  type :: plan_value_t
    !> Symbol in the program's notation ("v_B", "omega2", "a_CB^n", "eps3").
    character(len=24) :: name = ""
    !> How it is found ("pb*mu_v", "v_CB/l_CB", "v_CB^2/l_CB", "2*omega3*v_B2B3", "a_CB^t/l_CB").
    character(len=48) :: formula = ""
    !> Its value (magnitude), and its unit as the tables write it ("m/s", "rad/s", "m/s^2", "rad/s^2").
    real(wp) :: value = 0.0_wp
    character(len=8) :: unit = ""
    !> The sense of an angular quantity: "ccw", "cw" ("" for a linear one or zero).
    character(len=3) :: sense = ""
  end type plan_value_t

  !> The plans of one step.
  type :: plans_t
    !> Velocity images of the named points (and of the points of a guide's link under its
    !> sliders: B3), m/s.
    type(plan_vector_t), allocatable :: velocities(:)
    !> Acceleration images of the same points, m/s^2.
    type(plan_vector_t), allocatable :: accelerations(:)
    !> The vector equations of the acceleration plan, in drawing order.
    type(plan_equation_t), allocatable :: equations(:)
    !> The same equations on the plan of velocities: the relative velocities (v_CB = omega x
    !> (C - B), a slider's v_B2B3 along its guide), in drawing order.
    type(plan_equation_t), allocatable :: velocity_equations(:)
    !> The units of the structure, in the structure formula's order (input units first).
    type(plan_group_t), allocatable :: groups(:)
    !> Largest residual of the velocity equations, m/s, and of the acceleration equations, m/s^2.
    real(wp) :: velocity_residual = 0.0_wp, acceleration_residual = 0.0_wp
    !> Force polygons, one per link with known forces.
    type(force_polygon_t), allocatable :: polygons(:)
    !> Force polygons of the units of the structure, in the order kinetostatics solves them
    !> (the last group first, the input units last).
    type(force_polygon_t), allocatable :: group_polygons(:)
    !> The turn of the sheet's drawing against the position frame (gravity down the sheet), deg.
    real(wp) :: sheet_rotation = 0.0_wp
    !> Zhukovsky's lever: the driver's name, whether it could be computed, the effort from the
    !> lever and the table's value (N*m or N).
    character(len=:), allocatable :: driver
    logical :: lever_known = .false.
    real(wp) :: effort = 0.0_wp, run = 0.0_wp
    !> Why the lever is not known (when it is not).
    character(len=:), allocatable :: lever_note
    !> Every load of the lever's equation, and the balancing force (or couple) it finds.
    type(lever_load_t), allocatable :: loads(:)
    type(lever_load_t) :: balancing
    !> The balancing force's arm on the mechanism: the driving link's length from its pivot to
    !> the point P_bal acts at (M = P_bal * l), m; 0 for a force driver.
    real(wp) :: balancing_length = 0.0_wp
    !> Scale of the lever's arms: the driving link's rate (rad/s, or m/s for an actuator).
    real(wp) :: lever_rate = 0.0_wp
    !> Its symbol: omega<link> for a driving moment, v_rel for an actuator.
    character(len=:), allocatable :: lever_rate_name
    !> Friction in the pairs on the lever (the table has P_loss_<pair> columns): every pair's
    !> actions, their total power (W) and its share of the effort, -power/lever_rate.
    logical :: lever_friction = .false.
    type(lever_friction_t), allocatable :: friction(:)
    real(wp) :: friction_power = 0.0_wp, friction_share = 0.0_wp
    !> The true motion of a steady cycle (a DYNAMICS block with J_flywheel): the flywheel and
    !> the rotor turn with the driving link, their inertia J (kg*m^2) and inertia moment
    !> -J*eps on it (N*m) are on the lever.
    logical :: lever_flywheel = .false.
    real(wp) :: flywheel_inertia = 0.0_wp, flywheel_moment = 0.0_wp
    !> The values table: speeds, angular speeds, accelerations as read off the plans.
    type(plan_value_t), allocatable :: values(:)
  end type plans_t

contains

  !> Field of a link at point p: velocity v0 + omega x p, or acceleration a0 + eps x p -
  !> omega^2 p.
  pure function field(c, om, ep, p, accel) result(f)
    real(wp), intent(in) :: c(2), om, ep, p(2)
    logical, intent(in) :: accel
    real(wp) :: f(2)
    if (accel) then
      f = c + ep * [-p(2), p(1)] - om**2 * p
    else
      f = c + om * [-p(2), p(1)]
    end if
  end function field

  !> Velocity of the point p (m) carried by link l (0: the frame, at rest), m/s, from the links'
  !> velocity fields' terms v0 and angular velocities omega.
  pure function point_velocity(v0, omega, l, p) result(v)
    real(wp), intent(in) :: v0(:, :), omega(:), p(2)
    integer, intent(in) :: l
    real(wp) :: v(2)
    v = 0.0_wp
    if (l > 0) v = field(v0(:, l), omega(l), 0.0_wp, p, .false.)
  end function point_velocity

  !> z component of a x b.
  pure real(wp) function cross(a, b)
    real(wp), intent(in) :: a(2), b(2)
    cross = a(1) * b(2) - a(2) * b(1)
  end function cross

  !> a turned by 90 deg counterclockwise.
  pure function perp(a) result(b)
    real(wp), intent(in) :: a(2)
    real(wp) :: b(2)
    b = [-a(2), a(1)]
  end function perp

  !> Index of the link named `name` in the topology (0 if none); a number no link is named
  !> after is the link "L<number>" when there is one (an &assur deck's link 1 that is not the
  !> crank, whose pair forces are still F14, F21).
  pure integer function link_index(topo, name)
    type(sketch_t), intent(in) :: topo
    character(*), intent(in) :: name
    integer :: i
    link_index = 0
    do i = 1, size(topo%links)
      if (topo%links(i)%name == name) link_index = i
    end do
    if (link_index > 0 .or. len_trim(name) == 0) return
    do i = 1, size(topo%links)
      if (topo%links(i)%name == "L"//trim(name)) link_index = i
    end do
  end function link_index

  !> Whether link i lists point `p` (its own points, and its centre of mass S<name>; S1 for
  !> the link "L1").
  pure logical function lists(topo, i, p)
    type(sketch_t), intent(in) :: topo
    integer, intent(in) :: i
    character(*), intent(in) :: p
    lists = any(topo%links(i)%points == p) .or. p == "S"//topo%links(i)%name
    if (p(1:min(1, len(p))) == "S" .and. len(p) > 1) lists = lists .or. link_index(topo, p(2:)) == i
  end function lists

  !> Whether point `p` of link i is a sliding contact (a guide of link i passes through p and
  !> another link lists p: the block sliding there) rather than a point of the link.
  pure logical function sliding_on(topo, i, p)
    type(sketch_t), intent(in) :: topo
    integer, intent(in) :: i
    character(*), intent(in) :: p
    integer :: j
    sliding_on = .false.
    if (.not. any([(j /= i .and. lists(topo, j, p), j=1, size(topo%links))])) return
    if (allocated(topo%guides)) then
      do j = 1, size(topo%guides)
        if (topo%guides(j)%point == p .and. allocated(topo%guides(j)%on)) then
          if (topo%guides(j)%on == topo%links(i)%name) sliding_on = .true.
        end if
      end do
    end if
  end function sliding_on

  !> The link carrying the guide link `m` slides on (0 if none): a guide through one of m's
  !> points, or through a point on the line of which m turns with the guide's link.
  pure integer function guide_link(topo, m)
    type(sketch_t), intent(in) :: topo
    integer, intent(in) :: m
    integer :: j, g
    guide_link = 0
    if (m == 0 .or. .not. allocated(topo%guides)) return
    do j = 1, size(topo%guides)
      if (.not. allocated(topo%guides(j)%on)) cycle
      g = link_index(topo, topo%guides(j)%on)
      if (g == 0 .or. g == m) cycle
      guide_link = g
      if (lists(topo, m, trim(topo%guides(j)%point))) return
    end do
  end function guide_link

  !> The sliders of the step, in the order of the equations: guides (on a link, or on the
  !> frame) with the links listing their point, a rod in a cylinder (a guide on a moving link
  !> through a point only that link lists) and blocks sliding along a link. The rod is the
  !> first link with a point on the cylinder's axis that turns with the cylinder at every
  !> step of the run (its omega column equals the cylinder's), so the sliders - and with
  !> them the equations and the groups - are the same at every step, a step at rest included.
  pure subroutine slides_of(topo, drawing, table, k, slides)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(slide_t), allocatable, intent(out) :: slides(:)
    integer :: nl, i, j, m, g, ip, rod
    real(wp) :: p(2), u(2), ang, q(2)
    character(len=16) :: qname
    nl = size(topo%links)
    allocate (slides(0))
    if (allocated(topo%guides)) then
      do j = 1, size(topo%guides)
        associate (gd => topo%guides(j))
          ip = drawing%point_index(trim(gd%point))
          if (ip == 0) cycle
          p = drawing%points(ip)%p
          g = 0
          if (allocated(gd%on)) g = link_index(topo, gd%on)
          ang = gd%angle * deg_to_rad
          if (g > 0) ang = ang + column_value(table, "phi"//topo%links(g)%name, k) * deg_to_rad
          u = [cos(ang), sin(ang)]
          rod = 0
          do m = 1, nl
            if (m == g) cycle
            if (lists(topo, m, trim(gd%point))) then
              slides = [slides, slide_t(m, g, p, u, gd%point, gd%angle, .false.)]
            else if (g > 0 .and. rod == 0 .and. .not. listed_by_any(trim(gd%point), g)) then
              ! a rod in a cylinder: a link turning with the guide's link over the whole run,
              ! with a point on the axis
              if (.not. turns_with(m, g)) cycle
              do i = 1, size(topo%links(m)%points)
                qname = topo%links(m)%points(i)
                if (drawing%point_index(trim(qname)) == 0) cycle
                q = drawing%at(trim(qname))
                if (abs(cross(q - p, u)) <= 1.0e-9_wp * (1.0_wp + norm2(q - p))) then
                  slides = [slides, slide_t(m, g, q, u, qname, gd%angle, .false.)]
                  rod = m
                  exit
                end if
              end do
            end if
          end do
        end associate
      end do
    end if
    do m = 1, nl
      associate (l => topo%links(m))
        if (.not. l%block .or. .not. allocated(l%along)) cycle
        g = link_index(topo, l%along)
        if (g == 0) cycle
        ip = drawing%point_index(trim(l%points(1)))
        if (ip == 0) cycle
        ang = (l%angle + column_value(table, "phi"//l%along, k)) * deg_to_rad
        slides = [slides, slide_t(m, g, drawing%points(ip)%p, [cos(ang), sin(ang)], l%points(1), l%angle, .true.)]
      end associate
    end do
  contains
    !> Whether some link other than g lists the point.
    pure logical function listed_by_any(name, g)
      character(*), intent(in) :: name
      integer, intent(in) :: g
      integer :: q
      listed_by_any = .false.
      do q = 1, nl
        if (q /= g .and. lists(topo, q, name)) listed_by_any = .true.
      end do
    end function listed_by_any
    !> Whether link m turns with link g at every row of the table (their omega columns equal
    !> within 1e-12 of the larger); a link without an omega column does not.
    pure logical function turns_with(m, g)
      integer, intent(in) :: m, g
      integer :: cm, cg
      cm = table%column_index("omega"//topo%links(m)%name)
      cg = table%column_index("omega"//topo%links(g)%name)
      turns_with = cm > 0 .and. cg > 0
      if (.not. turns_with) return
      turns_with = all(abs(table%rows(cm, :) - table%rows(cg, :)) <= 1.0e-12_wp * max(abs(table%rows(cm, :)), &
        abs(table%rows(cg, :))))
    end function turns_with
  end subroutine slides_of

  !> Whether slide s is a pair of its own: a guide of the frame or of a link whose point
  !> several links list belongs to the block among them (a bar through the block's joint
  !> does not slide).
  pure logical function slide_is_pair(topo, slides, s)
    type(sketch_t), intent(in) :: topo
    type(slide_t), intent(in) :: slides(:)
    integer, intent(in) :: s
    integer :: t
    slide_is_pair = .true.
    if (topo%links(slides(s)%m)%block) return
    do t = 1, size(slides)
      if (t /= s .and. slides(t)%name == slides(s)%name .and. slides(t)%g == slides(s)%g) then
        if (topo%links(slides(t)%m)%block) slide_is_pair = .false.
      end if
    end do
  end function slide_is_pair

  !> The link of the driving moment `driver` (0: none) and the slider of a driving force
  !> between a slider and its guide's link (0: none).
  pure subroutine driver_links(topo, drawing, driver, crank, actuator)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    character(*), intent(in) :: driver
    integer, intent(out) :: crank, actuator
    integer :: j
    character(len=:), allocatable :: o
    crank = 0
    actuator = 0
    if (len_trim(driver) == 0) return
    if (allocated(drawing%moments)) then
      do j = 1, size(drawing%moments)
        if (drawing%moments(j)%name /= driver) cycle
        o = owner(drawing%moments(j)%name, drawing%moments(j)%on_link)
        crank = link_index(topo, o)
      end do
    end if
    if (crank == 0 .and. allocated(drawing%forces)) then
      do j = 1, size(drawing%forces)
        if (drawing%forces(j)%name == driver .and. drawing%forces(j)%kind /= force_pair) then
          actuator = link_index(topo, owner(drawing%forces(j)%name, drawing%forces(j)%on_link))
        end if
      end do
    end if
  end subroutine driver_links

  !> The link a force or moment belongs to: its own `link`, or the number in its name
  !> (G3, Phi3, MPhi3, M1: link 3, 3, 3, 1; F21: link 2, the pair force on 2 from 1).
  pure function owner(name, link) result(l)
    character(*), intent(in) :: name, link
    character(len=:), allocatable :: l
    l = trim(link)
    if (len(l) > 0) return
    if (name(1:1) == "G" .and. len_trim(name) > 1) then
      l = trim(name(2:))
    else if (index(name, "MPhi") == 1) then
      l = trim(name(5:))
    else if (index(name, "Phi") == 1) then
      l = trim(name(4:))
    else if (name(1:1) == "F" .and. len_trim(name) == 3 .and. verify(name(2:3), "0123456789") == 0) then
      l = name(2:2)
    else if (name(1:1) == "M" .and. len_trim(name) > 1) then
      if (verify(trim(name(2:)), "0123456789") == 0) l = trim(name(2:))
    end if
  end function owner

  !> The pivot of link i (a point of it fixed on the frame; "" for none).
  pure function pivot_of(topo, i) result(name)
    type(sketch_t), intent(in) :: topo
    integer, intent(in) :: i
    character(len=:), allocatable :: name
    integer :: j, k
    name = ""
    if (.not. allocated(topo%pivots) .or. i == 0) return
    associate (points => topo%links(i)%points)
      j = findloc([(any(topo%pivots == points(k)), k = 1, size(points))], .true., dim=1)
      if (j > 0) name = trim(points(j))
    end associate
  end function pivot_of

  !> The name of the point of link `link` at point `point` ("B3"; "J21_3" when the point's
  !> name ends in a digit).
  pure function coincident(point, link) result(text)
    character(*), intent(in) :: point, link
    character(len=:), allocatable :: text
    text = point
    if (len(point) == 0) return
    if (verify(point(len(point):), "0123456789") == 0) text = text//"_"
    text = text//link
  end function coincident

  !> The image of the point called `name` on a plan ((0, 0), the pole, for a blank name).
  pure function image_of(images, name) result(v)
    type(plan_vector_t), intent(in) :: images(:)
    character(*), intent(in) :: name
    real(wp) :: v(2)
    integer :: j
    v = 0.0_wp
    if (len_trim(name) == 0) return
    do j = 1, size(images)
      if (images(j)%name == name) v = images(j)%v
    end do
  end function image_of

  !> How far a polygon is from closing: |sum of its vectors| / its largest vector (0 when
  !> every vector is zero).
  pure real(wp) function closure_of(vectors)
    type(plan_vector_t), intent(in) :: vectors(:)
    real(wp) :: largest
    integer :: j
    largest = 0.0_wp
    do j = 1, size(vectors)
      largest = max(largest, norm2(vectors(j)%v))
    end do
    closure_of = 0.0_wp
    if (largest > 0.0_wp) closure_of = norm2([sum(vectors%v(1)), sum(vectors%v(2))]) / largest
  end function closure_of

end module kinetostat_plans_base
