!> The graphical method's plans at one step, computed from the drawing of that step (points,
!> forces, moments: kinetostat_drawing), the mechanism's topology (kinetostat_sketch) and the
!> kinematics columns (link angular velocities omega<i> and accelerations eps<i>,
!> accelerations of the centres of mass ax_S<i>, ay_S<i>):
!> - the plan of velocities: the image of every named point (v = v0_L + omega_L x r on each
!>   link L; the link's v0_L from the pairs: a pivot is at rest, a revolute joint has one
!>   velocity on both its links, a slider moves along its guide relative to the guide's
!>   link), solved in the least-squares sense, every equation's residual reported;
!> - the plan of accelerations: the same with a = a0_L + eps_L x r - omega_L^2 r, the centres
!>   of mass given by the table, the Coriolis term 2 omega_G x v_rel in the sliders;
!> - the force polygon of every link whose forces are known (its loads in a fixed order:
!>   weight, inertia force, external loads; then the pair forces on it): a closed polygon
!>   when the link is in (d'Alembert) equilibrium;
!> - Zhukovsky's lever: the balancing moment from the power of every force and moment but
!>   the driving one, -(sum F . v + sum M omega) / omega_driver, against the table's value.
module kinetostat_plans
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_pair, column_value
  use kinetostat_format, only: full_number
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_text, only: int_str
  use kinetostat_escape, only: json_string
  implicit none
  private
  public :: plans_t, plan_vector_t, force_polygon_t, plan_equation_t, lever_friction_t, build_plans, write_plans_json
  public :: component_normal, component_tangential, component_coriolis, component_relative, component_reaction

  !> A named vector (a point's image on a plan, a force of a polygon).
  type :: plan_vector_t
    !> Name ("B", "G2", "F21", "a_CB^τ": up to two joint names of 16 bytes each and a
    !> component's marks, so no name is cut).
    character(len=48) :: name = ""
    !> Components (position frame): m/s, m/s^2 or N.
    real(wp) :: v(2) = 0.0_wp
    !> A component's kind (component_normal ... on the acceleration plan; "" otherwise).
    character(len=1) :: kind = ""
  end type plan_vector_t

  !> Kinds of the acceleration components: normal (centripetal, omega^2 l toward the centre),
  !> tangential (eps x l), Coriolis (2 omega x v_rel), relative (sliding, along the guide).
  character(len=1), parameter :: component_normal = "n", component_tangential = "t", &
    component_coriolis = "k", component_relative = "r"
  !> Kind of a whole (unsplit) reaction in a group's force polygon.
  character(len=1), parameter :: component_reaction = "f"

  !> One vector equation of the acceleration plan, as the graphical method adds it: the
  !> image of `point` = the image of `from` (the pole when blank) + the components in order.
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
    !> The components in drawing order, m/s^2.
    type(plan_vector_t), allocatable :: vectors(:)
    !> A slider's equation the other way round: `point` is a point of the guide's link
    !> `link`, `from` the slider's point; the Coriolis term is the guide's point's relative
    !> to the slider, 2 omega_slider x (v_link - v_slider) at `from`.
    logical :: reverse = .false.
  end type plan_equation_t

  !> An Assur group (or the input link): its links (indices in the topology).
  type :: plan_group_t
    integer, allocatable :: links(:)
    !> Whether it is the input link.
    logical :: input = .false.
  end type plan_group_t

  !> A slider: link m moves along u (a unit vector) relative to link g (0: the frame) at the
  !> point p of m, called `name`.
  type :: slide_t
    integer :: m = 0, g = 0
    real(wp) :: p(2) = 0.0_wp, u(2) = 0.0_wp
    character(len=16) :: name = ""
  end type slide_t

  !> The force polygon of one link.
  type :: force_polygon_t
    !> Link name.
    character(len=16) :: link = ""
    !> The vectors in drawing order.
    type(plan_vector_t), allocatable :: vectors(:)
    !> |sum of the vectors| / largest vector (0 for a closed polygon).
    real(wp) :: closure = 0.0_wp
    !> The input link's polygon: the balancing moment's name ("" for none) and value, N*m.
    character(len=:), allocatable :: moment
    real(wp) :: moment_value = 0.0_wp
  end type force_polygon_t

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

  !> The plans of one step.
  type :: plans_t
    !> Velocity images of the named points, m/s.
    type(plan_vector_t), allocatable :: velocities(:)
    !> Acceleration images of the named points, m/s^2.
    type(plan_vector_t), allocatable :: accelerations(:)
    !> The vector equations of the acceleration plan, in drawing order.
    type(plan_equation_t), allocatable :: equations(:)
    !> The same equations on the plan of velocities: the relative velocities (v_CB = omega x
    !> (C - B), a slider's v_B^r along its guide), in drawing order.
    type(plan_equation_t), allocatable :: velocity_equations(:)
    !> The Assur groups, in the order they are solved.
    type(plan_group_t), allocatable :: groups(:)
    !> Largest residual of the velocity equations, m/s, and of the acceleration equations, m/s^2.
    real(wp) :: velocity_residual = 0.0_wp, acceleration_residual = 0.0_wp
    !> Force polygons, one per link with known forces.
    type(force_polygon_t), allocatable :: polygons(:)
    !> Force polygons of the input link and of every Assur group, in the order solved.
    type(force_polygon_t), allocatable :: group_polygons(:)
    !> Zhukovsky's lever: the driver's name, whether it could be computed, the effort from the
    !> lever and the table's value (N*m or N).
    character(len=:), allocatable :: driver
    logical :: lever_known = .false.
    real(wp) :: effort = 0.0_wp, run = 0.0_wp
    !> Why the lever is not known (when it is not).
    character(len=:), allocatable :: lever_note
    !> The loads on the lever: each force (N) and the velocity image of its point (m/s).
    type(plan_vector_t), allocatable :: lever_forces(:), lever_images(:)
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
  end type plans_t

  !> A pair equation between the fields of two links at a point: kind and data.
  integer, parameter :: eq_rest = 1, eq_joint = 2, eq_slide = 3

contains

  !> The plans of row `k` from the topology, the drawing (with its forces) and the table.
  pure subroutine build_plans(topo, drawing, table, k, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(plans_t), intent(out) :: plans
    real(wp), allocatable :: omega(:), eps(:), v0(:, :), a0(:, :), none(:, :)
    type(slide_t), allocatable :: slides(:)
    character(len=:), allocatable :: driver
    integer :: nl, i
    nl = size(topo%links)
    allocate (omega(nl), eps(nl))
    do i = 1, nl
      omega(i) = column_value(table, "omega"//topo%links(i)%name, k)
      eps(i) = column_value(table, "eps"//topo%links(i)%name, k)
    end do
    allocate (none(2, nl))
    none = 0.0_wp
    call solve_fields(topo, drawing, table, k, omega, eps, .false., none, v0, plans%velocity_residual)
    call solve_fields(topo, drawing, table, k, omega, eps, .true., v0, a0, plans%acceleration_residual)
    call point_images(topo, drawing, omega, eps, v0, .false., plans%velocities)
    call point_images(topo, drawing, omega, eps, a0, .true., plans%accelerations)
    driver = ""
    if (allocated(table%driver)) driver = table%driver
    call slides_of(topo, drawing, table, k, omega, slides)
    call groups_of(topo, drawing, slides, driver, plans%groups)
    call equations_of(topo, drawing, table, k, omega, eps, v0, plans)
    call velocity_equations_of(topo, drawing, omega, plans)
    call polygons_of(topo, drawing, driver, plans%polygons)
    call group_polygons_of(topo, drawing, table, k, slides, driver, plans%groups, plans%group_polygons)
    call lever_of(topo, drawing, table, k, omega, v0, plans)
  end subroutine build_plans

  !> Field of link `i` at point p: velocity v0 + omega x p, or acceleration
  !> a0 + eps x p - omega^2 p.
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

  !> Solve the links' unknown terms (v0 or a0) from the pair equations, least squares.
  pure subroutine solve_fields(topo, drawing, table, k, omega, eps, accel, v0, c, residual)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:), eps(:)
    logical, intent(in) :: accel
    !> The velocity solution (used for the Coriolis terms when accel).
    real(wp), intent(in) :: v0(:, :)
    real(wp), allocatable, intent(out) :: c(:, :)
    real(wp), intent(out) :: residual
    real(wp), allocatable :: a(:, :), b(:), x(:)
    type(slide_t), allocatable :: slides(:)
    integer :: nl, i, j, ip
    real(wp) :: p(2)
    character(len=16) :: pname
    nl = size(topo%links)
    allocate (a(0, 2 * nl), b(0))
    do ip = 1, size(drawing%points)
      pname = drawing%points(ip)%name
      p = drawing%points(ip)%p
      do i = 1, nl
        if (.not. lists(topo, i, trim(pname))) cycle
        if (sliding_on(topo, i, trim(pname))) cycle
        ! a pivot: at rest
        if (allocated(topo%pivots)) then
          if (any(topo%pivots == pname)) call append_rows(a, b, joint_rows(i, 0, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), -own(i, p))
        end if
        ! a joint with every later link listing the point
        do j = i + 1, nl
          if (.not. lists(topo, j, trim(pname))) cycle
          if (sliding_on(topo, j, trim(pname))) cycle
          call append_rows(a, b, joint_rows(i, j, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), own(j, p) - own(i, p))
        end do
      end do
      ! centres of mass with given accelerations
      if (accel .and. pname(1:1) == "S") then
        i = link_index(topo, trim(pname(2:)))
        if (i > 0 .and. table%column_index("ax_"//trim(pname)) > 0) then
          call append_rows(a, b, joint_rows(i, 0, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), [column_value(table, "ax_"//trim(pname), k), &
            column_value(table, "ay_"//trim(pname), k)] - own(i, p))
        end if
      end if
    end do
    ! sliders: guides (on a link, or on the frame) and blocks sliding along a link
    call slides_of(topo, drawing, table, k, omega, slides)
    do j = 1, size(slides)
      call append_slide(a, b, slide_row(slides(j)%m, slides(j)%g, slides(j)%p, slides(j)%u))
    end do
    ! least squares: the normal equations, a link without an equation stays at rest
    call least_squares(a, b, x)
    allocate (c(2, nl))
    c = reshape(x, [2, nl])
    residual = 0.0_wp
    if (size(b) > 0) residual = maxval(abs(matmul(a, x) - b))
  contains
    !> The link's own part of its field at p (without the unknown term).
    pure function own(i, p) result(f)
      integer, intent(in) :: i
      real(wp), intent(in) :: p(2)
      real(wp) :: f(2)
      f = field([0.0_wp, 0.0_wp], omega(i), eps(i), p, accel)
    end function own
    !> Rows c_i - c_j = rhs (j = 0: c_i = rhs) with the 2x2 coefficient block `blk` (column-major).
    pure function joint_rows(i, j, blk) result(rows)
      integer, intent(in) :: i, j
      real(wp), intent(in) :: blk(4)
      real(wp) :: rows(2, 2 * nl)
      rows = 0.0_wp
      rows(:, 2 * i - 1:2 * i) = reshape(blk, [2, 2])
      if (j > 0) rows(:, 2 * j - 1:2 * j) = -reshape(blk, [2, 2])
    end function joint_rows
    !> Link m slides along u on link g (0: the frame) at p: (f_m(p) - f_g(p) - cor) x u = 0,
    !> cor = 2 omega_g x v_rel the Coriolis acceleration (0 on the velocity plan), so
    !> c_m x u - c_g x u = (own_g - own_m + cor) x u: the row and its right-hand side.
    pure function slide_row(m, g, p, u) result(row_rhs)
      integer, intent(in) :: m, g
      real(wp), intent(in) :: p(2), u(2)
      real(wp) :: row_rhs(2 * nl + 1), vrel(2), cor(2)
      row_rhs = 0.0_wp
      row_rhs(2 * m - 1:2 * m) = [u(2), -u(1)]
      cor = 0.0_wp
      if (g > 0) then
        row_rhs(2 * g - 1:2 * g) = [-u(2), u(1)]
        if (accel) then
          vrel = field(v0(:, m), omega(m), 0.0_wp, p, .false.) - field(v0(:, g), omega(g), 0.0_wp, p, .false.)
          cor = 2.0_wp * omega(g) * [-vrel(2), vrel(1)]
        end if
        row_rhs(2 * nl + 1) = cross(own(g, p) - own(m, p) + cor, u)
      else
        row_rhs(2 * nl + 1) = cross(-own(m, p), u)
      end if
    end function slide_row
  end subroutine solve_fields

  !> The sliders of the step, in the order of the equations: guides (on a link, or on the
  !> frame) with the links listing their point, a rod turning with a cylinder's link along
  !> its guide, and blocks sliding along a link.
  pure subroutine slides_of(topo, drawing, table, k, omega, slides)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:)
    type(slide_t), allocatable, intent(out) :: slides(:)
    integer :: nl, i, j, m, g, ip
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
          do m = 1, nl
            if (m == g) cycle
            if (lists(topo, m, trim(gd%point))) then
              slides = [slides, slide_t(m, g, p, u, gd%point)]
            else if (g > 0 .and. .not. listed_by_any(trim(gd%point), g)) then
              ! a rod in a cylinder: the link turning with the guide's link that has a point on its line
              if (omega(m) /= omega(g)) cycle
              do i = 1, size(topo%links(m)%points)
                qname = topo%links(m)%points(i)
                if (drawing%point_index(trim(qname)) == 0) cycle
                q = drawing%at(trim(qname))
                if (abs(cross(q - p, u)) <= 1.0e-9_wp * (1.0_wp + norm2(q - p))) then
                  slides = [slides, slide_t(m, g, q, u, qname)]
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
        slides = [slides, slide_t(m, g, drawing%points(ip)%p, [cos(ang), sin(ang)], l%points(1))]
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

  !> The link of the driving moment (0: none) and the slider of a driving force between a
  !> slider and its guide's link (0: none).
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
        if (len(o) == 0 .and. driver(1:1) == "M" .and. verify(trim(driver(2:)), "0123456789") == 0) o = trim(driver(2:))
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

  !> The Assur groups in the order the graphical method solves them: the input link (the
  !> driving moment's link; none for a driving force in a cylinder, whose pair is then left
  !> out of the structure), then every dyad - two links sharing a pair, each with exactly one
  !> pair to the frame or to the links already solved - in link order; links left over (a
  !> group of a higher class) form the last group.
  pure subroutine groups_of(topo, drawing, slides, driver, groups)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(slide_t), intent(in) :: slides(:)
    character(*), intent(in) :: driver
    type(plan_group_t), allocatable, intent(out) :: groups(:)
    integer, allocatable :: pa(:), pb(:)
    logical, allocatable :: solved(:)
    integer :: nl, i, j, ip, s, crank, actuator, g
    logical :: found
    nl = size(topo%links)
    allocate (pa(0), pb(0), groups(0), solved(0:nl))
    ! the pairs: revolute (a point two links list, a pivot), prismatic (the slides)
    do ip = 1, size(drawing%points)
      associate (pname => drawing%points(ip)%name)
        do i = 1, nl
          if (.not. lists(topo, i, trim(pname)) .or. sliding_on(topo, i, trim(pname))) cycle
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == pname)) pb = [pb, 0]
            if (any(topo%pivots == pname)) pa = [pa, i]
          end if
          do j = i + 1, nl
            if (.not. lists(topo, j, trim(pname)) .or. sliding_on(topo, j, trim(pname))) cycle
            pa = [pa, i]
            pb = [pb, j]
          end do
        end do
      end associate
    end do
    call driver_links(topo, drawing, driver, crank, actuator)
    do s = 1, size(slides)
      if (.not. slide_is_pair(topo, slides, s)) cycle
      if (actuator > 0) then
        if (slides(s)%m == actuator .and. slides(s)%g == guide_link(topo, actuator)) cycle
      end if
      pa = [pa, slides(s)%m]
      pb = [pb, slides(s)%g]
    end do
    solved = .false.
    solved(0) = .true.
    if (crank > 0) then
      solved(crank) = .true.
      groups = [groups, plan_group_t([crank], .true.)]
    end if
    do
      found = .false.
      outer: do i = 1, nl
        if (solved(i)) cycle outer
        inner: do j = i + 1, nl
          if (solved(j)) cycle inner
          if (count(pair_of(i, j)) == 0) cycle inner
          if (to_solved(i) /= 1 .or. to_solved(j) /= 1) cycle inner
          groups = [groups, plan_group_t([i, j], .false.)]
          solved([i, j]) = .true.
          found = .true.
          exit outer
        end do inner
      end do outer
      if (.not. found) exit
    end do
    if (.not. all(solved)) then
      g = count(.not. solved(1:))
      groups = [groups, plan_group_t(pack([(i, i=1, nl)], .not. solved(1:)), .false.)]
    end if
  contains
    pure function pair_of(a, b) result(mask)
      integer, intent(in) :: a, b
      logical :: mask(size(pa))
      mask = (pa == a .and. pb == b) .or. (pa == b .and. pb == a)
    end function pair_of
    !> Number of pairs of link a with solved links (the frame included).
    pure integer function to_solved(a)
      integer, intent(in) :: a
      integer :: q
      to_solved = 0
      do q = 1, size(pa)
        if (pa(q) == a .and. solved(pb(q))) to_solved = to_solved + 1
        if (pb(q) == a .and. solved(pa(q))) to_solved = to_solved + 1
      end do
    end function to_solved
  end subroutine groups_of

  !> The velocity plan's equations from the acceleration plan's, term by term: a pair of
  !> normal and tangential components about a point Q of link L becomes the relative
  !> velocity v_PQ = omega_L x (P - Q); a Coriolis component has no velocity term; a
  !> relative (sliding) component becomes the slider's velocity along its guide, v_P^r, the
  !> rest of the equation (image of P - image of Q - the other terms).
  pure subroutine velocity_equations_of(topo, drawing, omega, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    !> Angular velocities of the topology's links, rad/s.
    real(wp), intent(in) :: omega(:)
    type(plans_t), intent(inout) :: plans
    type(plan_equation_t) :: veq
    real(wp) :: r(2), w, rest(2)
    integer :: e, j, i, relative_at
    allocate (plans%velocity_equations(size(plans%equations)))
    do e = 1, size(plans%equations)
      associate (eq => plans%equations(e))
        veq = eq
        w = 0.0_wp
        do i = 1, size(topo%links)
          if (topo%links(i)%name == eq%link) w = omega(i)
        end do
        r = drawing%at(trim(eq%point)) - drawing%at(trim(eq%from))
        deallocate (veq%vectors)
        allocate (veq%vectors(0))
        relative_at = 0
        do j = 1, size(eq%vectors)
          associate (v => eq%vectors(j))
            select case (v%kind)
            case (component_normal)
              veq%vectors = [veq%vectors, plan_vector_t(velocity_name(v%name), w * [-r(2), r(1)], &
                component_tangential)]
            case (component_relative)
              veq%vectors = [veq%vectors, plan_vector_t(velocity_name(v%name), [0.0_wp, 0.0_wp], component_relative)]
              relative_at = size(veq%vectors)
            case default
              continue
            end select
          end associate
        end do
        if (relative_at > 0) then
          rest = image_of(plans%velocities, eq%point) - image_of(plans%velocities, eq%from)
          do j = 1, size(veq%vectors)
            if (j /= relative_at) rest = rest - veq%vectors(j)%v
          end do
          veq%vectors(relative_at)%v = rest
        end if
        plans%velocity_equations(e) = veq
      end associate
    end do
  contains
    !> "a_CB^n" -> "v_CB", "a_B^r" -> "v_B^r".
    pure function velocity_name(name) result(text)
      character(*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: hat
      hat = index(name, "^")
      text = "v"//name(2:)
      if (hat > 0 .and. name(hat + 1:) /= "r") text = "v"//name(2:hat - 1)
    end function velocity_name
  end subroutine velocity_equations_of

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

  !> The vector equations of the acceleration plan in the order the graphical method draws
  !> them, group by group (groups_of): a point of the group's links is drawn when every link
  !> of the group through it has a known point (a dyad's inner joint from both its outer
  !> joints), each link giving a_P = a_Q + a_PQ^n + a_PQ^tau (a_PQ^n = -omega^2 (P - Q), a_PQ^tau
  !> = eps x (P - Q); a_P^n, a_P^tau about a pivot); a slider on a moving guide of link g,
  !> a_P = a_Q(g) + a_P<g>Q^n + a_P<g>Q^tau + a_P^k + a_P^r (a_P^k = 2 omega_g x v_rel, a_P^r
  !> along the guide), also when P is known already (its other side); on a guide of the
  !> frame, a_P = a_P^r from the pole beside its other equations.
  pure subroutine equations_of(topo, drawing, table, k, omega, eps, v0, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:), eps(:), v0(:, :)
    type(plans_t), intent(inout) :: plans
    type(slide_t), allocatable :: slides(:)
    logical, allocatable :: known(:), fresh(:), written(:), member(:)
    integer :: n, ip, s, q, gr, t
    logical :: any_ready, relaxed
    n = size(plans%accelerations)
    allocate (plans%equations(0), known(n), fresh(n))
    known = .false.
    if (allocated(topo%pivots)) then
      do ip = 1, n
        known(ip) = any(topo%pivots == plans%accelerations(ip)%name)
      end do
    end if
    call slides_of(topo, drawing, table, k, omega, slides)
    allocate (written(size(slides)), member(size(topo%links)))
    written = .false.
    do s = 1, size(slides)
      written(s) = .not. slide_is_pair(topo, slides, s)
    end do
    do gr = 1, size(plans%groups)
      member = .false.
      member(plans%groups(gr)%links) = .true.
      relaxed = .false.
      do
        fresh = .false.
        any_ready = .false.
        do ip = 1, n
          if (known(ip) .or. .not. of_group(ip)) cycle
          if (.not. ready(ip, relaxed)) cycle
          any_ready = .true.
          fresh(ip) = .true.
          call write_point(ip, plans%equations, written)
          if (relaxed) exit
        end do
        ! the other side of sliders at known points
        do s = 1, size(slides)
          if (written(s) .or. slides(s)%g == 0) cycle
          if (.not. (member(slides(s)%m) .or. member(slides(s)%g))) cycle
          ip = plan_point_index(slides(s)%name)
          if (ip == 0) cycle
          if (.not. known(ip)) cycle
          q = known_point(slides(s)%g, ip)
          if (q == 0) then
            ! the guide's link has no known point yet: its point from the slider's, the other
            ! way round (a point of the guide's link = the slider's point + Coriolis + relative
            ! + its rotation about the slider's point)
            q = unknown_point(slides(s)%g)
            if (q == 0) cycle
            plans%equations = [plans%equations, reversed(s, ip, q)]
            fresh(q) = .true.
            do t = 1, size(slides)
              if (written(t) .or. slides(t)%g /= 0 .or. slides(t)%name /= plans%accelerations(q)%name) cycle
              plans%equations = [plans%equations, sliding(t, 0, q)]
              written(t) = .true.
              exit
            end do
          else
            plans%equations = [plans%equations, sliding(s, q, ip)]
          end if
          written(s) = .true.
          any_ready = .true.
        end do
        known = known .or. fresh
        if (any_ready) then
          relaxed = .false.
        else if (.not. relaxed) then
          relaxed = .true.
        else
          exit
        end if
      end do
    end do
    ! points of no group (a construction point), and sliders never written
    do ip = 1, n
      if (.not. known(ip) .and. ready(ip, .true.)) call write_point(ip, plans%equations, written)
    end do
  contains
    !> Index of the image called `name` (0: none).
    pure integer function plan_point_index(name)
      character(*), intent(in) :: name
      integer :: t
      plan_point_index = 0
      do t = 1, n
        if (plans%accelerations(t)%name == name) plan_point_index = t
      end do
    end function plan_point_index
    !> Whether a link of the group lists the point (not as a sliding contact).
    pure logical function of_group(ip)
      integer, intent(in) :: ip
      integer :: t
      of_group = .false.
      do t = 1, size(topo%links)
        if (.not. member(t)) cycle
        if (lists(topo, t, trim(plans%accelerations(ip)%name)) .and. .not. &
          sliding_on(topo, t, trim(plans%accelerations(ip)%name))) of_group = .true.
      end do
    end function of_group
    !> Whether point ip can be drawn: every group link through it (and the guide's link of
    !> every slider there) has a known point; relaxed: at least one has.
    pure logical function ready(ip, relaxed)
      integer, intent(in) :: ip
      logical, intent(in) :: relaxed
      integer :: t, sides, open
      sides = 0
      open = 0
      do t = 1, size(topo%links)
        if (.not. lists(topo, t, trim(plans%accelerations(ip)%name)) .or. &
          sliding_on(topo, t, trim(plans%accelerations(ip)%name))) cycle
        if (known_point(t, ip) > 0) then
          sides = sides + 1
        else if (member(t)) then
          open = open + 1
        end if
      end do
      do t = 1, size(slides)
        if (written(t) .or. slides(t)%name /= plans%accelerations(ip)%name .or. slides(t)%g == 0) cycle
        if (known_point(slides(t)%g, ip) > 0) then
          sides = sides + 1
        else
          open = open + 1
        end if
      end do
      ready = sides > 0 .and. (open == 0 .or. relaxed)
    end function ready
    !> Every equation of point ip that its known points allow.
    pure subroutine write_point(ip, equations, written)
      integer, intent(in) :: ip
      type(plan_equation_t), allocatable, intent(inout) :: equations(:)
      logical, intent(inout) :: written(:)
      integer :: t, q, frame_slide
      do t = 1, size(topo%links)
        if (.not. lists(topo, t, trim(plans%accelerations(ip)%name)) .or. &
          sliding_on(topo, t, trim(plans%accelerations(ip)%name))) cycle
        q = known_point(t, ip)
        if (q > 0) equations = [equations, rotation(t, q, ip, "")]
      end do
      frame_slide = 0
      do t = 1, size(slides)
        if (written(t) .or. slides(t)%name /= plans%accelerations(ip)%name) cycle
        if (slides(t)%g == 0) then
          frame_slide = t
          cycle
        end if
        q = known_point(slides(t)%g, ip)
        if (q == 0) cycle
        equations = [equations, sliding(t, q, ip)]
        written(t) = .true.
      end do
      if (frame_slide > 0) then
        equations = [equations, sliding(frame_slide, 0, ip)]
        written(frame_slide) = .true.
      end if
    end subroutine write_point
    !> Index (on the plan) of the first known point of link i other than image `not` (0: none).
    pure integer function known_point(i, not)
      integer, intent(in) :: i, not
      known_point = first_point(i, .true., not)
    end function known_point
    !> Index of the first image that is a point of link i (not a sliding contact) and not
    !> known (0: none).
    pure integer function unknown_point(i)
      integer, intent(in) :: i
      unknown_point = first_point(i, .false., 0)
    end function unknown_point
    !> Index of the first image other than `not` that is a point of link i (not a sliding
    !> contact), known or not as `want_known` says (0: none).
    pure integer function first_point(i, want_known, not)
      integer, intent(in) :: i, not
      logical, intent(in) :: want_known
      integer :: t
      first_point = 0
      do t = 1, n
        if (t == not .or. (known(t) .neqv. want_known)) cycle
        associate (tname => plans%accelerations(t)%name)
          if (.not. lists(topo, i, trim(tname)) .or. sliding_on(topo, i, trim(tname))) cycle
        end associate
        first_point = t
        return
      end do
    end function first_point
    !> The name of the point of link `link` at point `point` ("B3"; "J21_3" when the point's
    !> name ends in a digit).
    pure function coincident(point, link) result(text)
      character(*), intent(in) :: point, link
      character(len=:), allocatable :: text
      text = point
      if (verify(point(len(point):), "0123456789") == 0) text = text//"_"
      text = text//link
    end function coincident
    !> Slider s the other way round: point t of its guide's link g from the slider's known
    !> point ip, a_t = a_P + a_P<g>^k + a_P<g>^r + a_tP<g>^n + a_tP<g>^tau, with the Coriolis
    !> term 2 omega_m x (v_g(P) - v_m(P)) of g's point relative to the slider m.
    pure function reversed(s, ip, t) result(eq)
      integer, intent(in) :: s, ip, t
      type(plan_equation_t) :: eq
      real(wp) :: vrel(2), cor(2), r(2), nrm(2), tng(2)
      integer :: m, g
      character(len=:), allocatable :: pg
      m = slides(s)%m
      g = slides(s)%g
      pg = coincident(trim(plans%accelerations(ip)%name), trim(topo%links(g)%name))
      vrel = field(v0(:, g), omega(g), 0.0_wp, slides(s)%p, .false.) - field(v0(:, m), omega(m), 0.0_wp, &
        slides(s)%p, .false.)
      cor = 2.0_wp * omega(m) * [-vrel(2), vrel(1)]
      r = drawing%at(trim(plans%accelerations(t)%name)) - drawing%at(trim(plans%accelerations(ip)%name))
      nrm = -omega(g)**2 * r
      tng = eps(g) * [-r(2), r(1)]
      eq%point = trim(plans%accelerations(t)%name)
      eq%link = topo%links(g)%name
      eq%from = trim(plans%accelerations(ip)%name)
      eq%slider = topo%links(m)%name
      eq%reverse = .true.
      eq%vectors = [plan_vector_t("a_"//pg//"^k", cor, component_coriolis), plan_vector_t("a_"//pg//"^r", &
        plans%accelerations(t)%v - plans%accelerations(ip)%v - cor - nrm - tng, component_relative), &
        plan_vector_t("a_"//trim(plans%accelerations(t)%name)//pg//"^n", nrm, component_normal), &
        plan_vector_t("a_"//trim(plans%accelerations(t)%name)//pg//"^τ", tng, component_tangential)]
    end function reversed
    !> Names of the normal and tangential components of P about Q on link i (`mid` the
    !> coincident point's link for a slider): a_PQ^n, or a_P^n when Q is a pivot.
    pure function relative_name(ip, q, mid) result(text)
      integer, intent(in) :: ip, q
      character(*), intent(in) :: mid
      character(len=:), allocatable :: text
      text = "a_"//mid
      if (len(mid) == 0) text = "a_"//trim(plans%accelerations(ip)%name)
      if (allocated(topo%pivots)) then
        if (any(topo%pivots == plans%accelerations(q)%name)) return
      end if
      text = text//trim(plans%accelerations(q)%name)
    end function relative_name
    !> a_P = a_Q + a_PQ^n + a_PQ^tau on link i.
    pure function rotation(i, q, ip, mid) result(eq)
      integer, intent(in) :: i, q, ip
      character(*), intent(in) :: mid
      type(plan_equation_t) :: eq
      real(wp) :: r(2)
      r = drawing%at(trim(plans%accelerations(ip)%name)) - drawing%at(trim(plans%accelerations(q)%name))
      eq%point = trim(plans%accelerations(ip)%name)
      eq%link = topo%links(i)%name
      eq%from = trim(plans%accelerations(q)%name)
      eq%vectors = [plan_vector_t(relative_name(ip, q, mid)//"^n", -omega(i)**2 * r, component_normal), &
        plan_vector_t(relative_name(ip, q, mid)//"^τ", eps(i) * [-r(2), r(1)], component_tangential)]
    end function rotation
    !> The slider s's equation from the known point q of its guide's link (q = 0: the frame's
    !> guide, from the pole): normal, tangential, Coriolis and relative components.
    pure function sliding(s, q, ip) result(eq)
      integer, intent(in) :: s, q, ip
      type(plan_equation_t) :: eq
      real(wp) :: vrel(2), cor(2), rest(2)
      integer :: m, g
      m = slides(s)%m
      g = slides(s)%g
      rest = 0.0_wp
      if (g > 0) then
        eq = rotation(g, q, ip, coincident(trim(plans%accelerations(ip)%name), trim(topo%links(g)%name)))
        eq%link = topo%links(g)%name
        vrel = field(v0(:, m), omega(m), 0.0_wp, slides(s)%p, .false.) - field(v0(:, g), omega(g), 0.0_wp, &
          slides(s)%p, .false.)
        cor = 2.0_wp * omega(g) * [-vrel(2), vrel(1)]
        rest = plans%accelerations(q)%v + eq%vectors(1)%v + eq%vectors(2)%v
        eq%vectors = [eq%vectors, plan_vector_t("a_"//trim(plans%accelerations(ip)%name)//"^k", cor, component_coriolis)]
        rest = rest + cor
      else
        eq%point = trim(plans%accelerations(ip)%name)
        eq%link = ""
        eq%from = ""
        allocate (eq%vectors(0))
      end if
      eq%slider = topo%links(m)%name
      eq%vectors = [eq%vectors, plan_vector_t("a_"//trim(plans%accelerations(ip)%name)//"^r", &
        plans%accelerations(ip)%v - rest, component_relative)]
    end function sliding
  end subroutine equations_of

  !> Append one slider's row (coefficients, then the right-hand side) to a x = b.
  pure subroutine append_slide(a, b, row_rhs)
    real(wp), allocatable, intent(inout) :: a(:, :), b(:)
    real(wp), intent(in) :: row_rhs(:)
    call append_rows(a, b, reshape(row_rhs(1:size(row_rhs) - 1), [1, size(row_rhs) - 1]), row_rhs(size(row_rhs):))
  end subroutine append_slide

  !> Append the rows (and their right-hand sides) to the system a x = b.
  pure subroutine append_rows(a, b, rows, rhs)
    real(wp), allocatable, intent(inout) :: a(:, :), b(:)
    real(wp), intent(in) :: rows(:, :), rhs(:)
    real(wp), allocatable :: grown(:, :)
    allocate (grown(size(a, 1) + size(rows, 1), size(a, 2)))
    grown(1:size(a, 1), :) = a
    grown(size(a, 1) + 1:, :) = rows
    call move_alloc(grown, a)
    b = [b, rhs]
  end subroutine append_rows

  !> z component of a x b.
  pure real(wp) function cross(a, b)
    real(wp), intent(in) :: a(2), b(2)
    cross = a(1) * b(2) - a(2) * b(1)
  end function cross

  !> Least-squares solution of a x = b through the normal equations (Gauss-Jordan with
  !> partial pivoting); an unknown without an equation is 0.
  pure subroutine least_squares(a, b, x)
    real(wp), intent(in) :: a(:, :), b(:)
    real(wp), allocatable, intent(out) :: x(:)
    real(wp), allocatable :: n(:, :), r(:), row(:)
    real(wp) :: t, scale
    integer :: i, j, p, m
    m = size(a, 2)
    n = matmul(transpose(a), a)
    r = matmul(transpose(a), b)
    scale = max(1.0_wp, maxval(abs(n)))
    allocate (x(m))
    x = 0.0_wp
    do i = 1, m
      p = i - 1 + maxloc(abs(n(i:, i)), 1)
      if (abs(n(p, i)) <= 1.0e-12_wp * scale) cycle
      if (p /= i) then
        row = n(i, :)
        n(i, :) = n(p, :)
        n(p, :) = row
        t = r(i)
        r(i) = r(p)
        r(p) = t
      end if
      t = n(i, i)
      n(i, :) = n(i, :) / t
      r(i) = r(i) / t
      do j = 1, m
        if (j == i .or. n(j, i) == 0.0_wp) cycle
        t = n(j, i)
        n(j, :) = n(j, :) - t * n(i, :)
        r(j) = r(j) - t * r(i)
      end do
    end do
    do i = 1, m
      if (abs(n(i, i) - 1.0_wp) <= 1.0e-9_wp) x(i) = r(i)
    end do
  end subroutine least_squares

  !> The image of every named point on a plan: the field of a link listing it (not as a
  !> sliding contact); points no link lists are left out.
  pure subroutine point_images(topo, drawing, omega, eps, c, accel, images)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    real(wp), intent(in) :: omega(:), eps(:), c(:, :)
    logical, intent(in) :: accel
    type(plan_vector_t), allocatable, intent(out) :: images(:)
    integer :: ip, i
    allocate (images(0))
    do ip = 1, size(drawing%points)
      do i = 1, size(topo%links)
        if (.not. lists(topo, i, trim(drawing%points(ip)%name))) cycle
        if (sliding_on(topo, i, trim(drawing%points(ip)%name))) cycle
        images = [images, plan_vector_t(drawing%points(ip)%name, &
          field(c(:, i), omega(i), eps(i), drawing%points(ip)%p, accel))]
        exit
      end do
    end do
  end subroutine point_images

  !> The link a force or moment belongs to: its own `link`, or the number in its name
  !> (G3, Phi3, MPhi3: link 3; F21: link 2, the pair force on 2 from 1).
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
    end if
  end function owner

  !> The force polygon of every link: its loads (weight, inertia force, external loads), then
  !> the pair forces on it (F<L><j> as written, F<j><L> reversed).
  pure subroutine polygons_of(topo, drawing, driver, polygons)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    !> The table's driving effort (a force whose reaction acts on the guide's link).
    character(*), intent(in) :: driver
    type(force_polygon_t), allocatable, intent(out) :: polygons(:)
    type(force_polygon_t) :: poly
    integer :: i, j, pass
    logical :: mine, take
    allocate (polygons(0))
    if (.not. allocated(drawing%forces)) return
    do i = 1, size(topo%links)
      poly%link = topo%links(i)%name
      allocate (poly%vectors(0))
      do pass = 1, 4
        do j = 1, size(drawing%forces)
          associate (f => drawing%forces(j))
            mine = link_index(topo, owner(f%name, f%on_link)) == i
            select case (pass)
            case (1)
              take = f%name(1:1) == "G" .and. mine
            case (2)
              take = f%name(1:3) == "Phi" .and. mine
            case (3)
              take = f%kind /= force_pair .and. f%name(1:1) /= "G" .and. f%name(1:3) /= "Phi" .and. mine
            case default
              take = .false.
            end select
            if (take) poly%vectors = [poly%vectors, plan_vector_t(f%name, f%f)]
            ! a load between a slider and its guide's link (an actuator): its reaction on the guide's link
            if (pass == 3 .and. f%kind /= force_pair .and. len_trim(f%on_link) > 0) then
              if (guide_link(topo, link_index(topo, trim(f%on_link))) == i .and. trim(f%name) == trim(driver)) then
                poly%vectors = [poly%vectors, plan_vector_t("-"//f%name, -f%f)]
              end if
            end if
            if (pass == 4 .and. f%kind == force_pair) then
              if (link_index(topo, owner(f%name, f%on_link)) == i) then
                poly%vectors = [poly%vectors, plan_vector_t(f%name, f%f)]
              else if (len_trim(f%name) == 3 .and. link_index(topo, f%name(3:3)) == i) then
                poly%vectors = [poly%vectors, plan_vector_t("F"//f%name(3:3)//f%name(2:2), -f%f)]
              end if
            end if
          end associate
        end do
      end do
      if (size(poly%vectors) > 0) then
        poly%closure = closure_of(poly%vectors)
        polygons = [polygons, poly]
      end if
      deallocate (poly%vectors)
    end do
  end subroutine polygons_of

  !> The force polygon of every Assur group as the graphical method closes it, from the last
  !> group attached to the first and then the input link: the known forces of its links link
  !> by link (weight, inertia force, external loads), the reactions of the groups solved
  !> before it (known now), then the unknown reactions of the frame and of the links it is
  !> attached to - a revolute pair's
  !> reaction on a link with another joint in the group split into its tangential part
  !> (perpendicular to the line to that joint, found from the link's moments) and its normal
  !> part (along it) - the tangential parts first, then the normal parts and the unsplit
  !> reactions, which close the polygon. The input link's polygon carries the balancing
  !> moment's name and value.
  pure subroutine group_polygons_of(topo, drawing, table, k, slides, driver, groups, polygons)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(slide_t), intent(in) :: slides(:)
    character(*), intent(in) :: driver
    type(plan_group_t), intent(in) :: groups(:)
    type(force_polygon_t), allocatable, intent(out) :: polygons(:)
    type(force_polygon_t) :: poly
    type(plan_vector_t), allocatable :: tangential(:), closing(:)
    logical, allocatable :: member(:), before(:)
    integer :: gr, q, i, j, a, b, pass, crank, actuator, cylinder
    logical :: take
    allocate (polygons(0), member(size(topo%links)), before(0:size(topo%links)))
    ! a cylinder drive: the cylinder and its rod are one body of the group (their pair is
    ! the input)
    call driver_links(topo, drawing, driver, crank, actuator)
    cylinder = 0
    if (actuator > 0) cylinder = guide_link(topo, actuator)
    if (.not. allocated(drawing%forces)) return
    before = .false.
    do gr = size(groups), 1, -1
      member = .false.
      member(groups(gr)%links) = .true.
      poly%link = ""
      do q = 1, size(groups(gr)%links)
        if (q > 1) poly%link = trim(poly%link)//","
        poly%link = trim(poly%link)//topo%links(groups(gr)%links(q))%name
      end do
      allocate (poly%vectors(0), tangential(0), closing(0))
      do q = 1, size(groups(gr)%links)
        i = groups(gr)%links(q)
        do pass = 1, 3
          do j = 1, size(drawing%forces)
            associate (f => drawing%forces(j))
              if (f%kind == force_pair) cycle
              take = link_index(topo, owner(f%name, f%on_link)) == i
              select case (pass)
              case (1)
                take = take .and. f%name(1:1) == "G"
              case (2)
                take = take .and. f%name(1:3) == "Phi"
              case default
                take = take .and. f%name(1:1) /= "G" .and. f%name(1:3) /= "Phi"
              end select
              if (take) poly%vectors = [poly%vectors, plan_vector_t(f%name, f%f)]
              ! an actuator's force: its reaction on the guide's link
              if (pass == 3 .and. len_trim(f%on_link) > 0 .and. trim(f%name) == trim(driver)) then
                if (guide_link(topo, link_index(topo, trim(f%on_link))) == i) poly%vectors = [poly%vectors, &
                  plan_vector_t("-"//f%name, -f%f)]
              end if
            end associate
          end do
        end do
      end do
      ! the reactions on the group from the links outside it
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (f%kind /= force_pair .or. len_trim(f%name) /= 3 .or. f%name(1:1) /= "F") cycle
          a = link_index(topo, f%name(2:2))
          b = link_index(topo, f%name(3:3))
          if (a > 0 .and. member(max(a, 1)) .and. .not. (b > 0 .and. member(max(b, 1)))) then
            call add_reaction(trim(f%name), f%f, a, b, f%at, poly, tangential, closing)
          else if (b > 0 .and. member(max(b, 1)) .and. .not. (a > 0 .and. member(max(a, 1)))) then
            call add_reaction("F"//f%name(3:3)//f%name(2:2), -f%f, b, a, f%at, poly, tangential, closing)
          end if
        end associate
      end do
      ! the frame's reactions close the polygon
      poly%vectors = [poly%vectors, tangential, pack(closing, .not. from_frame(closing)), pack(closing, &
        from_frame(closing))]
      before(groups(gr)%links) = .true.
      poly%moment = ""
      poly%moment_value = 0.0_wp
      if (groups(gr)%input .and. table%column_index(driver) > 0) then
        poly%moment = driver
        poly%moment_value = column_value(table, driver, k)
      end if
      poly%closure = closure_of(poly%vectors)
      polygons = [polygons, poly]
      deallocate (poly%vectors, tangential, closing)
    end do
  contains
    !> Whether each reaction F<l><o> is from the frame (o no moving link).
    pure function from_frame(vectors) result(mask)
      type(plan_vector_t), intent(in) :: vectors(:)
      logical :: mask(size(vectors))
      integer :: t
      do t = 1, size(vectors)
        mask(t) = link_index(topo, vectors(t)%name(3:3)) == 0
      end do
    end function from_frame
    !> The reaction `f` (N) on link l of the group from link o (0: the frame) at `at`: split
    !> when the pair is revolute and l has another joint with a link of the group.
    pure subroutine add_reaction(name, f, l, o, at, poly, tangential, closing)
      character(*), intent(in) :: name
      real(wp), intent(in) :: f(2), at(2)
      integer, intent(in) :: l, o
      type(force_polygon_t), intent(inout) :: poly
      type(plan_vector_t), allocatable, intent(inout) :: tangential(:), closing(:)
      integer :: s
      real(wp) :: e(2), inner(2)
      logical :: split
      if (before(o)) then
        ! from a group solved before: a known force
        poly%vectors = [poly%vectors, plan_vector_t(name, f)]
        return
      end if
      call inner_joint(l, at, split, inner)
      do s = 1, size(slides)
        if ((slides(s)%m == l .and. slides(s)%g == o) .or. (slides(s)%m == o .and. slides(s)%g == l)) split = .false.
      end do
      ! a block's pin is its only joint, unless it is one body with the other half of a cylinder drive
      if (topo%links(l)%block .and. l /= actuator .and. l /= cylinder) split = .false.
      if (split) then
        e = (inner - at) / norm2(inner - at)
        tangential = [tangential, plan_vector_t(name//"^τ", f - dot_product(f, e) * e, component_tangential)]
        closing = [closing, plan_vector_t(name//"^n", dot_product(f, e) * e, component_normal)]
      else
        closing = [closing, plan_vector_t(name, f, component_reaction)]
      end if
    end subroutine add_reaction
    !> Whether link l has a joint (not at `at`) with another link of the group (`found`); its position.
    pure subroutine inner_joint(l, at, found, p)
      integer, intent(in) :: l
      real(wp), intent(in) :: at(2)
      logical, intent(out) :: found
      real(wp), intent(out) :: p(2)
      integer :: t, o, body, own
      found = .false.
      p = 0.0_wp
      ! the link, and the other half of a cylinder drive (one body with it)
      do own = 1, 2
        body = l
        if (own == 2) then
          body = 0
          if (l == actuator .and. cylinder > 0) body = cylinder
          if (l == cylinder .and. actuator > 0) body = actuator
          if (body == 0) return
          if (.not. member(body)) return
        end if
        do t = 1, size(topo%links(body)%points)
          associate (pname => topo%links(body)%points(t))
            if (drawing%point_index(trim(pname)) == 0 .or. sliding_on(topo, body, trim(pname))) cycle
            if (norm2(drawing%at(trim(pname)) - at) <= 1.0e-9_wp * (1.0_wp + norm2(at))) cycle
            do o = 1, size(topo%links)
              if (o == l .or. o == body .or. .not. member(o)) cycle
              if (lists(topo, o, trim(pname)) .and. .not. sliding_on(topo, o, trim(pname))) then
                found = .true.
                p = drawing%at(trim(pname))
                return
              end if
            end do
          end associate
        end do
      end do
    end subroutine inner_joint
  end subroutine group_polygons_of

  !> Zhukovsky's lever: the power of every load but the driving moment, over the driver's
  !> angular velocity (the balancing moment); for a driving force between a slider and its
  !> guide's link (a cylinder: F on one, -F on the other) over their relative velocity along
  !> it (the balancing force). The reactions of frictionless pairs do no work; friction in a
  !> pair (pair_friction_of) adds its two actions' power.
  pure subroutine lever_of(topo, drawing, table, k, omega, v0, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:), v0(:, :)
    type(plans_t), intent(inout) :: plans
    real(wp) :: power, rate, image(2)
    integer :: j, l, d, g, c
    logical :: actuator
    plans%driver = ""
    if (allocated(table%driver)) plans%driver = table%driver
    plans%lever_known = .false.
    plans%lever_note = ""
    if (table%column_index(plans%driver) == 0) then
      plans%lever_note = "no driver column"
      return
    end if
    plans%run = column_value(table, plans%driver, k)
    d = 0
    if (allocated(drawing%moments)) then
      do j = 1, size(drawing%moments)
        if (drawing%moments(j)%name == plans%driver) d = link_index(topo, owner_of_moment(j))
      end do
    end if
    ! or a force between a slider and its guide's link (a hydraulic cylinder): its power is
    ! F . (v_slider - v_guide), the same at every point of the slider
    rate = 0.0_wp
    actuator = .false.
    if (d == 0 .and. allocated(drawing%forces)) then
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (f%name /= plans%driver .or. plans%run == 0.0_wp) cycle
          l = link_index(topo, owner(f%name, f%on_link))
          g = guide_link(topo, l)
          if (l == 0 .or. g == 0) cycle
          actuator = .true.
          rate = dot_product(f%f / plans%run, field(v0(:, l), omega(l), 0.0_wp, f%at, .false.) - &
            field(v0(:, g), omega(g), 0.0_wp, f%at, .false.))
        end associate
      end do
      if (.not. actuator) then
        plans%lever_note = "the driver is neither a moment on a link nor a force on a slider of the drawing"
        return
      end if
    else if (d == 0) then
      plans%lever_note = "the driver is not a moment on a link of the drawing"
      return
    else
      rate = omega(d)
    end if
    plans%lever_rate_name = "v_rel"
    if (d > 0) plans%lever_rate_name = "omega"//trim(topo%links(d)%name)
    if (rate == 0.0_wp) then
      plans%lever_note = "the driving link is at rest"
      return
    end if
    power = 0.0_wp
    allocate (plans%lever_forces(0), plans%lever_images(0))
    plans%lever_rate = rate
    if (allocated(drawing%forces)) then
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (f%kind == force_pair .or. f%name == plans%driver) cycle
          l = link_index(topo, owner(f%name, f%on_link))
          if (l == 0) then
            plans%lever_note = "force "//trim(f%name)//" belongs to no known link"
            return
          end if
          image = field(v0(:, l), omega(l), 0.0_wp, f%at, .false.)
          power = power + dot_product(f%f, image)
          plans%lever_forces = [plans%lever_forces, plan_vector_t(f%name, f%f)]
          plans%lever_images = [plans%lever_images, plan_vector_t(f%name, image)]
        end associate
      end do
    end if
    do j = 1, size(drawing%moments)
      if (drawing%moments(j)%name == plans%driver) cycle
      l = link_index(topo, owner_of_moment(j))
      if (l == 0) then
        plans%lever_note = "moment "//trim(drawing%moments(j)%name)//" belongs to no known link"
        return
      end if
      power = power + drawing%moments(j)%value * omega(l)
    end do
    ! the true motion: the flywheel and the rotor on the driving link's shaft, -J eps on it
    if (d > 0 .and. table%dynamics_index("J_flywheel") > 0) then
      c = table%column_index("eps"//trim(topo%links(d)%name))
      if (c > 0) then
        plans%lever_flywheel = .true.
        plans%flywheel_inertia = table%shaft_inertia()
        plans%flywheel_moment = -plans%flywheel_inertia * table%rows(c, k)
        power = power + plans%flywheel_moment * omega(d)
      end if
    end if
    call pair_friction_of(topo, drawing, table, k, omega, v0, plans)
    if (len(plans%lever_note) > 0) return
    plans%friction_share = -plans%friction_power / rate
    plans%effort = -(power + plans%friction_power) / rate
    plans%lever_known = .true.
  contains
    pure function owner_of_moment(j) result(o)
      integer, intent(in) :: j
      character(len=:), allocatable :: o
      o = owner(drawing%moments(j)%name, drawing%moments(j)%on_link)
      if (len(o) == 0 .and. drawing%moments(j)%name(1:1) == "M" .and. &
        verify(trim(drawing%moments(j)%name(2:)), "0123456789") == 0) o = trim(drawing%moments(j)%name(2:))
    end function owner_of_moment
  end subroutine lever_of

  !> Friction in the pairs on Zhukovsky's lever. For every pair with a P_loss_<pair> column
  !> (the run's power lost in it, W): the equal and opposite actions on its two links (F21: on
  !> link 2 and on link 1; a link the topology does not have is the frame, at rest), opposing
  !> their relative motion on the plan - at a revolute pair a couple M_f, of size P_loss over
  !> |omega_2 - omega_1|, whose power on the lever is M_f omega_2 - M_f omega_1; at a prismatic
  !> pair (a <pair>N column) a force F_f along the relative sliding v_2 - v_1 (the same at
  !> every point: the links turn together), of size P_loss over |v_2 - v_1|, acting at the
  !> images of the pair's point on the two links, power F_f.v_2 - F_f.v_1. A pair at relative
  !> rest on the plan (within 1e-10 of its links' rates) contributes nothing. Sets
  !> plans%lever_note when a pair's links are not known.
  pure subroutine pair_friction_of(topo, drawing, table, k, omega, v0, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:), v0(:, :)
    type(plans_t), intent(inout) :: plans
    !> A relative rate at or below this fraction of the links' rates is rest.
    real(wp), parameter :: rest_rel = 1.0e-10_wp
    character(*), parameter :: loss_prefix = "P_loss_"
    type(lever_friction_t) :: pf
    character(len=:), allocatable :: pair
    real(wp) :: loss, size_rel, scale
    integer :: c, a, b, j
    allocate (plans%friction(0))
    plans%friction_power = 0.0_wp
    do c = 1, size(table%columns)
      if (index(table%columns(c)%name, loss_prefix) /= 1) cycle
      plans%lever_friction = .true.
      pair = trim(table%columns(c)%name(len(loss_prefix) + 1:))
      if (len(pair) /= 3 .or. pair(1:1) /= "F" .or. verify(pair(2:3), "0123456789") /= 0) then
        plans%lever_note = "friction of pair "//pair//": its links are not known"
        return
      end if
      pf = lever_friction_t(pair=pair, on=pair(2:2), from=pair(3:3))
      a = link_index(topo, pair(2:2))
      b = link_index(topo, pair(3:3))
      if (a == 0 .and. b == 0) then
        plans%lever_note = "friction of pair "//pair//": its links are not known"
        return
      end if
      loss = table%rows(c, k)
      pf%prismatic = table%column_index(pair//"N") > 0
      if (pf%prismatic) then
        if (allocated(drawing%forces)) then
          do j = 1, size(drawing%forces)
            if (drawing%forces(j)%name == pair) pf%at = drawing%forces(j)%at
          end do
        end if
        pf%relative = velocity(a, pf%at) - velocity(b, pf%at)
        size_rel = norm2(pf%relative)
        scale = norm2(velocity(a, pf%at)) + norm2(velocity(b, pf%at))
        if (size_rel > rest_rel * scale) pf%force = -loss / size_rel * pf%relative / size_rel
        pf%power = dot_product(pf%force, velocity(a, pf%at)) + dot_product(-pf%force, velocity(b, pf%at))
      else
        pf%relative = [rate_of(a) - rate_of(b), 0.0_wp]
        size_rel = abs(pf%relative(1))
        scale = abs(rate_of(a)) + abs(rate_of(b))
        if (size_rel > rest_rel * scale) pf%moment = -sign(loss / size_rel, pf%relative(1))
        pf%power = pf%moment * rate_of(a) + (-pf%moment) * rate_of(b)
      end if
      plans%friction = [plans%friction, pf]
      plans%friction_power = plans%friction_power + pf%power
    end do
  contains
    !> Angular velocity of link l (0: the frame), rad/s.
    pure real(wp) function rate_of(l)
      integer, intent(in) :: l
      rate_of = 0.0_wp
      if (l > 0) rate_of = omega(l)
    end function rate_of
    !> Velocity of the point p carried by link l (0: the frame), m/s.
    pure function velocity(l, p) result(v)
      integer, intent(in) :: l
      real(wp), intent(in) :: p(2)
      real(wp) :: v(2)
      v = 0.0_wp
      if (l > 0) v = field(v0(:, l), omega(l), 0.0_wp, p, .false.)
    end function velocity
  end subroutine pair_friction_of

  !> The plans as one JSON object (`--format json --at K --plans`).
  pure subroutine write_plans_json(plans, table, k, out)
    type(plans_t), intent(in) :: plans
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    type(text_buffer_t), intent(inout) :: out
    integer :: i
    character(len=:), allocatable :: line
    call out%put("{")
    call out%put('  "deck": '//json_string(table%deck)//',')
    call out%put('  "step": '//int_str(k)//',')
    if (table%input_column > 0) call out%put('  '//json_string(table%columns(table%input_column)%name)//': '// &
      full_number(table%rows(table%input_column, k))//',')
    call put_vectors(out, "velocity_plan", plans%velocities, "m/s")
    call out%put('  "velocity_residual": '//full_number(plans%velocity_residual)//',')
    call put_vectors(out, "acceleration_plan", plans%accelerations, "m/s^2")
    call out%put('  "acceleration_residual": '//full_number(plans%acceleration_residual)//',')
    call put_equations(out, "velocity_equations", plans%velocity_equations, .false.)
    call put_equations(out, "acceleration_equations", plans%equations, .true.)
    call out%put('  "force_plans": [')
    do i = 1, size(plans%group_polygons)
      associate (poly => plans%group_polygons(i))
        line = '    {"group": '//json_string(trim(poly%link))//', "closure": '//full_number(poly%closure)
        if (len(poly%moment) > 0) line = line//', "moment": {"name": '//json_string(poly%moment)//', "value": '// &
          full_number(poly%moment_value)//'}'
        line = line//', "vectors": ['//vectors_json(poly%vectors)//"]}"
      end associate
      call put_item(out, line, i < size(plans%group_polygons))
    end do
    call out%put("  ],")
    call out%put('  "link_force_plans": [')
    do i = 1, size(plans%polygons)
      line = '    {"link": '//json_string(trim(plans%polygons(i)%link))//', "closure": '//full_number(plans%polygons(i)%closure)// &
        ', "vectors": ['//vectors_json(plans%polygons(i)%vectors)//"]}"
      call put_item(out, line, i < size(plans%polygons))
    end do
    call out%put("  ],")
    if (plans%lever_known) then
      line = '  "zhukovsky": {"driver": '//json_string(plans%driver)//', "effort": '//full_number(plans%effort)// &
        ', "run": '//full_number(plans%run)
      if (plans%lever_flywheel) line = line//', "flywheel": {"J": '//full_number(plans%flywheel_inertia)// &
        ', "moment": '//full_number(plans%flywheel_moment)//'}'
      if (plans%lever_friction) then
        line = line//', "friction": {"power": '//full_number(plans%friction_power)//', "rate": '// &
          json_string(plans%lever_rate_name)//', "share": '//full_number(plans%friction_share)//', "pairs": ['
        do i = 1, size(plans%friction)
          if (i > 1) line = line//', '
          line = line//friction_json(plans%friction(i))
        end do
        line = line//']}'
      end if
      call out%put(line//'}')
    else
      call out%put('  "zhukovsky": {"driver": '//json_string(plans%driver)//', "effort": null, "run": '// &
        full_number(plans%run)//', "note": '//json_string(plans%lever_note)//'}')
    end if
    call out%put("}")
  end subroutine write_plans_json

  !> One pair's friction on the lever as a JSON object: {"pair", "on", "from", "moment" and
  !> "relative" (rad/s) at a revolute pair, "force", "at" and "relative" (m/s) as {x, y} at a
  !> prismatic one, "power" (W)}.
  pure function friction_json(pf) result(text)
    type(lever_friction_t), intent(in) :: pf
    character(len=:), allocatable :: text
    text = '{"pair": '//json_string(trim(pf%pair))//', "on": '//json_string(trim(pf%on))//', "from": '// &
      json_string(trim(pf%from))//', '
    if (pf%prismatic) then
      text = text//'"force": '//xy(pf%force)//', "at": '//xy(pf%at)//', "relative": '//xy(pf%relative)
    else
      text = text//'"moment": '//full_number(pf%moment)//', "relative": '//full_number(pf%relative(1))
    end if
    text = text//', "power": '//full_number(pf%power)//'}'
  contains
    pure function xy(v) result(t)
      real(wp), intent(in) :: v(2)
      character(len=:), allocatable :: t
      t = '{"x": '//full_number(v(1))//', "y": '//full_number(v(2))//'}'
    end function xy
  end function friction_json

  !> "key": {"unit": ..., "points": [vectors]}, as one member of the plans object.
  pure subroutine put_vectors(out, key, vectors, unit)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: key, unit
    type(plan_vector_t), intent(in) :: vectors(:)
    integer :: q
    call out%put('  "'//key//'": {"unit": "'//unit//'", "points": [')
    do q = 1, size(vectors)
      call put_item(out, "    "//vector_json(vectors(q)), q < size(vectors))
    end do
    call out%put("  ]},")
  end subroutine put_vectors

  !> The vector equations of a plan as a JSON array under `key`, each with its components in
  !> drawing order; `mark_reverse`: the reversed slider equations carry "reverse": true.
  pure subroutine put_equations(out, key, equations, mark_reverse)
    type(text_buffer_t), intent(inout) :: out
    !> The array's name.
    character(*), intent(in) :: key
    !> The equations.
    type(plan_equation_t), intent(in) :: equations(:)
    !> Whether to mark the reversed equations.
    logical, intent(in) :: mark_reverse
    character(len=:), allocatable :: line
    integer :: i
    call out%put('  "'//key//'": [')
    do i = 1, size(equations)
      associate (eq => equations(i))
        line = '    {"point": '//json_string(trim(eq%point))//', "link": '//json_string(trim(eq%link))//', "from": '// &
          json_string(trim(eq%from))//', "slider": '//json_string(trim(eq%slider))//', '
        if (mark_reverse .and. eq%reverse) line = line//'"reverse": true, '
        line = line//'"vectors": ['//vectors_json(eq%vectors)//"]}"
      end associate
      call put_item(out, line, i < size(equations))
    end do
    call out%put("  ],")
  end subroutine put_equations

  !> {"name": ..., "x": ..., "y": ...}.
  pure function vector_json(v) result(text)
    type(plan_vector_t), intent(in) :: v
    character(len=:), allocatable :: text
    text = '{"name": '//json_string(trim(v%name))//', '
    if (len_trim(v%kind) > 0) text = text//'"kind": '//json_string(v%kind)//', '
    text = text//'"x": '//full_number(v%v(1))//', "y": '//full_number(v%v(2))//"}"
  end function vector_json

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

  !> Vectors as JSON objects separated by commas.
  pure function vectors_json(vectors) result(text)
    type(plan_vector_t), intent(in) :: vectors(:)
    character(len=:), allocatable :: text
    integer :: j
    text = ""
    do j = 1, size(vectors)
      text = text//vector_json(vectors(j))
      if (j < size(vectors)) text = text//", "
    end do
  end function vectors_json

  !> One line of a JSON array, with a comma when more follow.
  pure subroutine put_item(out, line, more)
    type(text_buffer_t), intent(inout) :: out
    !> The item.
    character(*), intent(in) :: line
    !> Whether more items follow.
    logical, intent(in) :: more
    if (more) then
      call out%put(line//",")
    else
      call out%put(line)
    end if
  end subroutine put_item

end module kinetostat_plans
