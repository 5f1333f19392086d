!> The graphical method's plans at one step, computed from the drawing of that step (points,
!> forces, moments: kinetostat_drawing), the mechanism's topology (kinetostat_sketch) and the
!> kinematics columns (link angular velocities omega<i> and accelerations eps<i>,
!> accelerations of the centres of mass ax_S<i>, ay_S<i>):
!> - the plan of velocities: the image of every named point (v = v0_L + omega_L x r on each
!>   link L; the link's v0_L from the pairs: a pivot is at rest, a revolute joint has one
!>   velocity on both its links, a slider moves along its guide relative to the guide's
!>   link), solved in the least-squares sense, every equation's residual reported; the
!>   point of a guide's link under a slider (B3 under the block's B) has its image too;
!> - the plan of accelerations: the same with a = a0_L + eps_L x r - omega_L^2 r, the centres
!>   of mass given by the table, the Coriolis term 2 omega_G x v_rel in the sliders; the
!>   relative terms named by the two bodies (v_B2B3, a_B2B3^k, a_B2B3^r);
!> - the units of the structure and their force polygons (kinetostat_plans_groups), the
!>   force polygon of every link;
!> - Zhukovsky's lever (kinetostat_plans_lever);
!> - the values table: speeds, angular speeds with their senses, the acceleration
!>   components, angular accelerations, as the student writes them beside the plans.
module kinetostat_plans
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, column_value
  use kinetostat_plans_base, only: plans_t, plan_vector_t, plan_equation_t, plan_value_t, slide_t, &
    component_normal, component_tangential, component_coriolis, component_relative, field, cross, link_index, lists, &
    sliding_on, slides_of, slide_is_pair, image_of, coincident
  use kinetostat_plans_groups, only: plan_groups, group_polygons_of, link_polygons_of
  use kinetostat_plans_lever, only: lever_of
  implicit none
  private
  public :: build_plans, solve_fields, point_images, field_topology_t, field_topology

  !> What solve_fields and point_images read from the topology and the table's names for the
  !> points of a drawing (the same at every row of a run: found once when many rows are solved).
  type :: field_topology_t
    !> incident(ip, i): point ip is a point of link i (the link lists it, not as a sliding
    !> contact).
    logical, allocatable :: incident(:, :)
    !> pivot(ip): point ip is a pivot (at rest).
    logical, allocatable :: pivot(:)
    !> com_link(ip): for a centre of mass S<i> with an ax_S<i> column, the link i (else 0).
    integer, allocatable :: com_link(:)
    !> com_cols(:, ip): its ax_ and ay_ columns (0: none).
    integer, allocatable :: com_cols(:, :)
  end type field_topology_t

contains

  !> The field topology of `drawing`'s points (field_topology_t).
  pure function field_topology(topo, drawing, table) result(t)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    type(field_topology_t) :: t
    integer :: np, nl, ip, i
    character(len=16) :: pname
    np = size(drawing%points)
    nl = size(topo%links)
    allocate (t%incident(np, nl), t%pivot(np), t%com_link(np), t%com_cols(2, np))
    t%com_link = 0
    t%com_cols = 0
    do ip = 1, np
      pname = drawing%points(ip)%name
      do i = 1, nl
        t%incident(ip, i) = lists(topo, i, trim(pname))
        if (t%incident(ip, i)) t%incident(ip, i) = .not. sliding_on(topo, i, trim(pname))
      end do
      t%pivot(ip) = .false.
      if (allocated(topo%pivots)) t%pivot(ip) = any(topo%pivots == pname)
      if (pname(1:1) == "S") then
        i = link_index(topo, trim(pname(2:)))
        t%com_cols(:, ip) = [table%column_index("ax_"//trim(pname)), table%column_index("ay_"//trim(pname))]
        if (i > 0 .and. t%com_cols(1, ip) > 0) t%com_link(ip) = i
      end if
    end do
  end function field_topology

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
    plans%sheet_rotation = drawing%view_angle * rad_to_deg
    call solve_fields(topo, drawing, table, k, omega, eps, .false., none, v0, plans%velocity_residual)
    call solve_fields(topo, drawing, table, k, omega, eps, .true., v0, a0, plans%acceleration_residual)
    call point_images(topo, drawing, omega, eps, v0, .false., plans%velocities)
    call point_images(topo, drawing, omega, eps, a0, .true., plans%accelerations)
    driver = ""
    if (allocated(table%driver)) driver = table%driver
    call slides_of(topo, drawing, table, k, slides)
    call plan_groups(topo, drawing, table, slides, driver, plans%groups)
    call equations_of(topo, drawing, table, k, omega, eps, v0, plans)
    call velocity_equations_of(topo, drawing, omega, plans)
    call coincident_images(topo, slides, omega, eps, v0, a0, plans)
    call link_polygons_of(topo, drawing, driver, plans%polygons)
    call group_polygons_of(topo, drawing, table, k, slides, driver, plans%groups, plans%group_polygons)
    call lever_of(topo, drawing, table, k, omega, v0, plans)
    call values_of(topo, drawing, omega, eps, plans)
  end subroutine build_plans

  !> Solve the links' unknown terms (v0 or a0) from the pair equations, least squares.
  pure subroutine solve_fields(topo, drawing, table, k, omega, eps, accel, v0, c, residual, known)
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
    !> field_topology(topo, drawing, table), when the caller keeps it for many rows.
    type(field_topology_t), intent(in), optional :: known
    type(field_topology_t) :: t
    real(wp), allocatable :: a(:, :), b(:), x(:)
    type(slide_t), allocatable :: slides(:)
    integer :: nl, i, j, ip
    real(wp) :: p(2), ay
    nl = size(topo%links)
    if (present(known)) then
      t = known
    else
      t = field_topology(topo, drawing, table)
    end if
    allocate (a(0, 2 * nl), b(0))
    do ip = 1, size(drawing%points)
      p = drawing%points(ip)%p
      do i = 1, nl
        if (.not. t%incident(ip, i)) cycle
        ! a pivot: at rest
        if (t%pivot(ip)) call append_rows(a, b, joint_rows(i, 0, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), -own(i, p))
        ! a joint with every later link listing the point
        do j = i + 1, nl
          if (.not. t%incident(ip, j)) cycle
          call append_rows(a, b, joint_rows(i, j, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), own(j, p) - own(i, p))
        end do
      end do
      ! centres of mass with given accelerations
      if (accel .and. t%com_link(ip) > 0) then
        i = t%com_link(ip)
        ay = 0.0_wp
        if (t%com_cols(2, ip) > 0) ay = table%rows(t%com_cols(2, ip), k)
        call append_rows(a, b, joint_rows(i, 0, [1.0_wp, 0.0_wp, 0.0_wp, 1.0_wp]), [table%rows(t%com_cols(1, ip), k), &
          ay] - own(i, p))
      end if
    end do
    ! sliders: guides (on a link, or on the frame) and blocks sliding along a link
    call slides_of(topo, drawing, table, k, slides)
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

  !> The image of every named point on a plan: the field of a link listing it (not as a
  !> sliding contact); points no link lists are left out.
  pure subroutine point_images(topo, drawing, omega, eps, c, accel, images, known)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    real(wp), intent(in) :: omega(:), eps(:), c(:, :)
    logical, intent(in) :: accel
    type(plan_vector_t), allocatable, intent(out) :: images(:)
    !> field_topology(topo, drawing, table), when the caller keeps it for many rows.
    type(field_topology_t), intent(in), optional :: known
    integer :: ip, i
    logical :: incident
    allocate (images(0))
    do ip = 1, size(drawing%points)
      do i = 1, size(topo%links)
        if (present(known)) then
          incident = known%incident(ip, i)
        else
          incident = lists(topo, i, trim(drawing%points(ip)%name))
          if (incident) incident = .not. sliding_on(topo, i, trim(drawing%points(ip)%name))
        end if
        if (.not. incident) cycle
        images = [images, plan_vector_t(drawing%points(ip)%name, &
          field(c(:, i), omega(i), eps(i), drawing%points(ip)%p, accel))]
        exit
      end do
    end do
  end subroutine point_images

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
    !> "a_CB^n" -> "v_CB", "a_B2B3^r" -> "v_B2B3", "a_C" (a guide of the frame) -> "v_C".
    pure function velocity_name(name) result(text)
      character(*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: hat
      hat = index(name, "^")
      text = "v"//name(2:)
      if (hat > 0) text = "v"//name(2:hat - 1)
    end function velocity_name
  end subroutine velocity_equations_of

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
    call slides_of(topo, drawing, table, k, slides)
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
    !> Slider s the other way round: point t of its guide's link g from the slider's known
    !> point ip, a_t = a_P + a_P<g>^k + a_P<g>^r + a_tP<g>^n + a_tP<g>^tau, with the Coriolis
    !> term 2 omega_m x (v_g(P) - v_m(P)) of g's point relative to the slider m.
    pure function reversed(s, ip, t) result(eq)
      integer, intent(in) :: s, ip, t
      type(plan_equation_t) :: eq
      real(wp) :: vrel(2), cor(2), r(2), nrm(2), tng(2)
      integer :: m, g
      character(len=:), allocatable :: pg, pm
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
      pm = coincident(trim(plans%accelerations(ip)%name), trim(topo%links(m)%name))
      eq%vectors = [plan_vector_t("a_"//pg//pm//"^k", cor, component_coriolis), plan_vector_t("a_"//pg//pm//"^r", &
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
      character(len=:), allocatable :: rel
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
        rel = coincident(trim(plans%accelerations(ip)%name), trim(topo%links(m)%name))// &
          coincident(trim(plans%accelerations(ip)%name), trim(topo%links(g)%name))
        eq%vectors = [eq%vectors, plan_vector_t("a_"//rel//"^k", cor, component_coriolis)]
        rest = rest + cor
      else
        ! on a guide of the frame the sliding is the point's own motion: a_P along the guide
        eq%point = trim(plans%accelerations(ip)%name)
        eq%link = ""
        eq%from = ""
        allocate (eq%vectors(0))
        rel = trim(plans%accelerations(ip)%name)
      end if
      eq%slider = topo%links(m)%name
      if (g > 0) rel = rel//"^r"
      eq%vectors = [eq%vectors, plan_vector_t("a_"//rel, plans%accelerations(ip)%v - rest, component_relative)]
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

  !> The images of the points of a guide's link under its sliders (B3: the point of the
  !> slotted link 3 under the block's B), on both plans, after the named points; a point
  !> already there (a second slider at the same place) once.
  pure subroutine coincident_images(topo, slides, omega, eps, v0, a0, plans)
    type(sketch_t), intent(in) :: topo
    type(slide_t), intent(in) :: slides(:)
    real(wp), intent(in) :: omega(:), eps(:), v0(:, :), a0(:, :)
    type(plans_t), intent(inout) :: plans
    integer :: s, g, e
    do s = 1, size(slides)
      if (.not. slide_is_pair(topo, slides, s)) cycle
      g = slides(s)%g
      if (g == 0) cycle
      call add(plans, coincident(trim(slides(s)%name), trim(topo%links(g)%name)), g, slides(s)%p)
    end do
    ! a slider's equation the other way round names the guide's point on the guide's link
    ! (D5 under the block 4's D) and the slider's (D4)
    do e = 1, size(plans%equations)
      if (.not. plans%equations(e)%reverse) cycle
      do s = 1, size(slides)
        if (slides(s)%name /= plans%equations(e)%from .or. slides(s)%g == 0) cycle
        call add(plans, coincident(trim(slides(s)%name), trim(topo%links(slides(s)%g)%name)), slides(s)%g, slides(s)%p)
      end do
    end do
  contains
    pure subroutine add(plans, name, g, p)
      type(plans_t), intent(inout) :: plans
      character(*), intent(in) :: name
      integer, intent(in) :: g
      real(wp), intent(in) :: p(2)
      if (any(plans%velocities%name == name)) return
      plans%velocities = [plans%velocities, plan_vector_t(name, field(v0(:, g), omega(g), eps(g), p, .false.))]
      plans%accelerations = [plans%accelerations, plan_vector_t(name, field(a0(:, g), omega(g), eps(g), p, .true.))]
    end subroutine add
  end subroutine coincident_images

  !> The values table: every image's speed (v_B = pb mu_v), every relative velocity of a link's
  !> points (v_CB) and sliding velocity (v_B2B3), every moving link's angular speed from a
  !> relative velocity (omega2 = v_CB / l_CB) with its sense; every absolute acceleration,
  !> every acceleration component (a_CB^n = v_CB^2 / l_CB, a_CB^tau and a_B2B3^r read off the
  !> plan, a_B2B3^k = 2 omega3 v_B2B3), every angular acceleration (eps2 = a_CB^tau / l_CB)
  !> with its sense.
  pure subroutine values_of(topo, drawing, omega, eps, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    real(wp), intent(in) :: omega(:), eps(:)
    type(plans_t), intent(inout) :: plans
    type(plan_value_t), allocatable :: vals(:)
    real(wp) :: l, size_v, size_a
    integer :: e, j, li
    allocate (vals(0))
    size_v = tiny_of(plans%velocities)
    size_a = tiny_of(plans%accelerations)
    call put_absolutes(vals, plans%velocities, "v", "p", "mu_v", "m/s", size_v)
    do e = 1, size(plans%velocity_equations)
      associate (eq => plans%velocity_equations(e))
        do j = 1, size(eq%vectors)
          associate (v => eq%vectors(j))
            if (norm2(v%v) <= size_v) cycle
            if (v%kind == component_relative) then
              call put(vals, trim(v%name), "", norm2(v%v), "m/s", "")
            else if (len_trim(eq%from) > 0 .and. .not. pivot(eq%from)) then
              call put(vals, trim(v%name), image(eq%from)//image(eq%point)//"*mu_v", norm2(v%v), "m/s", "")
            end if
          end associate
        end do
      end associate
    end do
    ! every link's angular speed from its longest relative velocity (the most exact reading)
    call put_rates(vals, plans%velocity_equations, "omega", "rad/s", omega)
    call put_absolutes(vals, plans%accelerations, "a", "π", "mu_a", "m/s^2", size_a)
    do e = 1, size(plans%equations)
      associate (eq => plans%equations(e))
        li = link_index(topo, trim(eq%link))
        do j = 1, size(eq%vectors)
          associate (v => eq%vectors(j))
            if (norm2(v%v) <= size_a) cycle
            l = 0.0_wp
            if (len_trim(eq%from) > 0) l = norm2(drawing%at(trim(eq%point)) - drawing%at(trim(eq%from)))
            select case (v%kind)
            case (component_normal)
              call put(vals, trim(v%name), velocity_of(v%name)//"^2/l_"//segment(eq), norm2(v%v), "m/s^2", "")
            case (component_tangential)
              call put(vals, trim(v%name), "", norm2(v%v), "m/s^2", "")
            case (component_coriolis)
              call put(vals, trim(v%name), "2*omega"//trim(eq%link)//"*"//velocity_of(v%name), norm2(v%v), "m/s^2", "")
              if (eq%reverse) vals(size(vals))%formula = "2*omega"//trim(eq%slider)//"*"// &
                velocity_of(v%name)
            case default
              call put(vals, trim(v%name), "", norm2(v%v), "m/s^2", "")
            end select
          end associate
        end do
      end associate
    end do
    ! every link's angular acceleration from its longest tangential component
    call put_rates(vals, plans%equations, "eps", "rad/s^2", eps)
    call move_alloc(vals, plans%values)
  contains
    !> Every image's absolute velocity or acceleration (v_B = pb*mu_v), those too small to
    !> read left out.
    pure subroutine put_absolutes(vals, images, symbol, pole, scale, unit, smallest)
      type(plan_value_t), allocatable, intent(inout) :: vals(:)
      type(plan_vector_t), intent(in) :: images(:)
      !> "v" or "a"; the plan's pole ("p", "π"); its scale ("mu_v", "mu_a"); the unit.
      character(*), intent(in) :: symbol, pole, scale, unit
      !> The largest length left out.
      real(wp), intent(in) :: smallest
      integer :: i
      do i = 1, size(images)
        if (norm2(images(i)%v) <= smallest) cycle
        call put(vals, symbol//"_"//trim(images(i)%name), pole//image(images(i)%name)//"*"//scale, &
          norm2(images(i)%v), unit, "")
      end do
    end subroutine put_absolutes

    !> Every link's angular rate (omega or eps) from its longest tangential term: the term
    !> over the length of its two points, with the sense of the link's `rates`.
    pure subroutine put_rates(vals, equations, symbol, unit, rates)
      type(plan_value_t), allocatable, intent(inout) :: vals(:)
      type(plan_equation_t), intent(in) :: equations(:)
      character(*), intent(in) :: symbol, unit
      real(wp), intent(in) :: rates(:)
      integer :: q, eq_at, term
      real(wp) :: length
      do q = 1, size(topo%links)
        call longest(equations, q, eq_at, term, length)
        if (eq_at == 0) cycle
        associate (eq => equations(eq_at))
          call put(vals, symbol//trim(topo%links(q)%name), trim(eq%vectors(term)%name)//"/l_"//segment(eq), &
            norm2(eq%vectors(term)%v) / length, unit, sense(rates(q)))
        end associate
      end do
    end subroutine put_rates
    !> The equation e and its tangential component j on link li whose points are farthest
    !> apart (l, m); e = 0 when the link has none that is not zero.
    pure subroutine longest(equations, li, e, j, l)
      type(plan_equation_t), intent(in) :: equations(:)
      integer, intent(in) :: li
      integer, intent(out) :: e, j
      real(wp), intent(out) :: l
      integer :: q, t
      real(wp) :: r
      e = 0
      j = 0
      l = 0.0_wp
      do q = 1, size(equations)
        if (link_index(topo, trim(equations(q)%link)) /= li .or. len_trim(equations(q)%from) == 0) cycle
        do t = 1, size(equations(q)%vectors)
          if (equations(q)%vectors(t)%kind /= component_tangential) cycle
          if (norm2(equations(q)%vectors(t)%v) <= 0.0_wp) cycle
          r = norm2(drawing%at(trim(equations(q)%point)) - drawing%at(trim(equations(q)%from)))
          if (r > l) then
            e = q
            j = t
            l = r
          end if
        end do
      end do
    end subroutine longest
    !> The segment of an equation's link as the course names its length: l_CB (point, then the
    !> point it starts from), l_AB about a pivot A.
    pure function segment(eq) result(text)
      type(plan_equation_t), intent(in) :: eq
      character(len=:), allocatable :: text
      text = trim(eq%point)//trim(eq%from)
      if (pivot(eq%from)) text = trim(eq%from)//trim(eq%point)
    end function segment
    !> Append a line (once per name).
    pure subroutine put(vals, name, formula, value, unit, how)
      type(plan_value_t), allocatable, intent(inout) :: vals(:)
      character(*), intent(in) :: name, formula, unit, how
      real(wp), intent(in) :: value
      if (any(vals%name == name)) return
      vals = [vals, plan_value_t(name, formula, value, unit, how)]
    end subroutine put
    !> Whether the point is a pivot (its image is the pole).
    pure logical function pivot(name)
      character(*), intent(in) :: name
      pivot = .false.
      if (allocated(topo%pivots)) pivot = any(topo%pivots == name)
    end function pivot
    !> The image's letter as the plan names it ("b", "b3").
    pure function image(name) result(text)
      character(*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: q
      text = trim(name)
      do q = 1, len(text)
        if (text(q:q) >= "A" .and. text(q:q) <= "Z") text(q:q) = achar(iachar(text(q:q)) + 32)
      end do
    end function image
    !> The velocity term of an acceleration component: a_CB^n -> v_CB.
    pure function velocity_of(name) result(text)
      character(*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: hat
      hat = index(name, "^")
      text = "v"//trim(name(2:))
      if (hat > 0) text = "v"//name(2:hat - 1)
    end function velocity_of
    !> The sense of an angular rate: counterclockwise, clockwise.
    pure function sense(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      text = ""
      if (x > 0.0_wp) text = "ccw"
      if (x < 0.0_wp) text = "cw"
    end function sense
    !> What counts as zero on a plan: 1e-9 of its largest image.
    pure real(wp) function tiny_of(images)
      type(plan_vector_t), intent(in) :: images(:)
      integer :: q
      tiny_of = 0.0_wp
      do q = 1, size(images)
        tiny_of = max(tiny_of, norm2(images(q)%v))
      end do
      tiny_of = 1.0e-9_wp * tiny_of
    end function tiny_of
  end subroutine values_of

end module kinetostat_plans
