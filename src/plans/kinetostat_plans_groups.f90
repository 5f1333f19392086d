!> The units of the structure the graphical method solves one by one, and their force
!> polygons in the course's order:
!> - `plan_groups`, the one place the plans take their groups from: the mechanism's own
!>   structural analysis when its sketch carries one (`&linkage`), else a decomposition
!>   derived from the topology that the structural analysis gives for the same mechanism
!>   (the input link, the dyads in link order, what is left one group) - the same at every
!>   step of a run;
!> - the force polygon of every unit, from the last group to the input units: for a dyad
!>   (links a, b; a the one attached to a moving link) F_a^tau, the loads of a, the loads of
!>   b (with the reactions of the groups solved before), F_b^tau, F_b^n, F_a^n - the whole
!>   reactions drawn, and the inner reaction found from a's polygon; for a group of a higher
!>   class each outer link's reaction (tau, n) then its loads, in pair order, the base link's
!>   loads last, each outer link's inner reaction with the base found from its polygon; an
!>   input unit's loads, the known reactions, then the frame's reaction;
!> - the force polygon of every link (its loads, then the pair forces on it).
module kinetostat_plans_groups
  use kinetostat_kinds, only: wp
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_pair, column_value
  use kinetostat_plans_base, only: plan_group_t, plan_vector_t, force_polygon_t, plan_reaction_t, slide_t, &
    component_tangential, component_normal, component_reaction, link_index, lists, sliding_on, guide_link, &
    slide_is_pair, driver_links, owner, closure_of
  implicit none
  private
  public :: plan_groups, group_polygons_of, link_polygons_of

  !> One reaction of a group's polygon: its parts (tangential and normal, or the whole).
  type :: reaction_parts_t
    character(len=16) :: name = ""
    type(plan_vector_t), allocatable :: parts(:)
    !> Whether it comes from a moving link (not the frame).
    logical :: from_moving = .false.
  end type reaction_parts_t

  !> The known loads of one body of a group.
  type :: load_list_t
    type(plan_vector_t), allocatable :: v(:)
  end type load_list_t

contains

  !> The units of the structure, in the structure formula's order (input units first): the
  !> mechanism's own structural analysis (topo%groups) when it has one, else derived from
  !> the topology (derived_groups). This is the only place the plans take their groups from.
  pure subroutine plan_groups(topo, drawing, table, slides, driver, groups)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    type(slide_t), intent(in) :: slides(:)
    !> The table's driving effort ("M1", "F2").
    character(*), intent(in) :: driver
    type(plan_group_t), allocatable, intent(out) :: groups(:)
    integer :: g, i, j
    if (allocated(topo%groups)) then
      if (size(topo%groups) > 0) then
        allocate (groups(size(topo%groups)))
        do g = 1, size(topo%groups)
          associate (sg => topo%groups(g))
            allocate (groups(g)%links(0))
            do i = 1, size(sg%links)
              j = link_index(topo, trim(sg%links(i)))
              if (j > 0) groups(g)%links = [groups(g)%links, j]
            end do
            groups(g)%class = sg%class
            groups(g)%input = sg%class == 1
            groups(g)%label = sg%label
            groups(g)%drive = ""
            if (groups(g)%input) groups(g)%drive = drive_of(groups(g)%links)
          end associate
        end do
        do g = 1, size(groups)
          groups(g)%names = [character(len=16) :: (topo%links(groups(g)%links(i))%name, i=1, size(groups(g)%links))]
        end do
        return
      end if
    end if
    call derived_groups(topo, drawing, slides, driver, groups)
    do g = 1, size(groups)
      groups(g)%names = [character(len=16) :: (topo%links(groups(g)%links(i))%name, i=1, size(groups(g)%links))]
    end do
  contains
    !> The drive effort of an input unit: the table's driver when it acts on one of its links,
    !> else the moment M<link> (a drive's effort) on one of them, else F_drive<link>.
    pure function drive_of(links) result(name)
      integer, intent(in) :: links(:)
      character(len=:), allocatable :: name
      integer :: q, c, a
      integer :: crank, actuator
      name = ""
      call driver_links(topo, drawing, driver, crank, actuator)
      if (any(links == crank) .or. any(links == actuator)) then
        name = driver
        return
      end if
      do q = 1, size(links)
        a = links(q)
        c = table%column_index("M"//topo%links(a)%name)
        if (c > 0 .and. moment_drawn("M"//topo%links(a)%name)) then
          name = "M"//topo%links(a)%name
          return
        end if
        if (table%column_index("F_drive"//topo%links(a)%name) > 0) name = "F_drive"//topo%links(a)%name
      end do
    end function drive_of
    !> Whether the drawing has the moment `name`.
    pure logical function moment_drawn(name)
      character(*), intent(in) :: name
      integer :: q
      moment_drawn = .false.
      if (.not. allocated(drawing%moments)) return
      do q = 1, size(drawing%moments)
        if (drawing%moments(q)%name == name) moment_drawn = .true.
      end do
    end function moment_drawn
  end subroutine plan_groups

  !> The units of the structure derived from the topology, for a mechanism whose sketch
  !> carries no structural analysis: the input link (the driving moment's link; none for a
  !> driving force in a cylinder, whose pair is then left out of the structure), then every
  !> dyad - two links sharing a pair, each with exactly one pair to the frame or to the links
  !> already placed - in link order; links left over form the last unit: an input unit when
  !> the drive acts inside it (a cylinder between two of its links: PR 3050's I(0,1,2,3)),
  !> else a group of a higher class. Pairs and drives are topological, so the units are the
  !> same at every step. The structural analysis (kinetostat structure) of the same
  !> mechanism written as a &linkage deck gives the same units.
  pure subroutine derived_groups(topo, drawing, slides, driver, groups)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(slide_t), intent(in) :: slides(:)
    character(*), intent(in) :: driver
    type(plan_group_t), allocatable, intent(out) :: groups(:)
    integer, allocatable :: pa(:), pb(:), rest(:)
    logical, allocatable :: solved(:)
    integer :: nl, i, j, ip, s, crank, actuator
    logical :: found
    character(len=:), allocatable :: frame
    nl = size(topo%links)
    allocate (pa(0), pb(0), groups(0), solved(0:nl))
    ! the pairs: revolute (a point two links list, a pivot), prismatic (the slides)
    do ip = 1, size(drawing%points)
      associate (pname => drawing%points(ip)%name)
        do i = 1, nl
          if (.not. lists(topo, i, trim(pname)) .or. sliding_on(topo, i, trim(pname))) cycle
          if (allocated(topo%pivots)) then
            if (any(topo%pivots == pname)) then
              pa = [pa, i]
              pb = [pb, 0]
            end if
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
    frame = frame_number(topo, drawing)
    solved = .false.
    solved(0) = .true.
    if (crank > 0) then
      solved(crank) = .true.
      groups = [groups, plan_group_t([crank], null(), .true., 1, "I("//frame//","// &
        group_links_text(topo, [crank], .true.)//")", driver)]
    end if
    do
      found = .false.
      outer: do i = 1, nl
        if (solved(i)) cycle outer
        inner: do j = i + 1, nl
          if (solved(j)) cycle inner
          if (count(pair_of(i, j)) == 0) cycle inner
          if (to_solved(i) /= 1 .or. to_solved(j) /= 1) cycle inner
          groups = [groups, plan_group_t([i, j], null(), .false., 2, "II("//group_links_text(topo, [i, j], .true.)// &
            ")", "")]
          solved([i, j]) = .true.
          found = .true.
          exit outer
        end do inner
      end do outer
      if (.not. found) exit
    end do
    if (.not. all(solved)) then
      rest = pack([(i, i=1, nl)], .not. solved(1:))
      if (actuator > 0 .and. any(rest == actuator)) then
        groups = [groups, plan_group_t(rest, null(), .true., 1, "I("//frame//","// &
          group_links_text(topo, rest, .true.)//")", driver)]
      else if (size(rest) == 4 .or. size(rest) == 6) then
        groups = [groups, plan_group_t(rest, null(), .false., 3, "III("//group_links_text(topo, rest, .true.)//")", "")]
      else
        groups = [groups, plan_group_t(rest, null(), .false., 0, "("//group_links_text(topo, rest, .true.)//")", "")]
      end if
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
  end subroutine derived_groups

  !> The frame's number as the pair forces name it (the second digit of a force F<i><j>
  !> whose j is no moving link; "0" when no force says).
  pure function frame_number(topo, drawing) result(name)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    character(len=:), allocatable :: name
    integer :: j
    name = "0"
    if (.not. allocated(drawing%forces)) return
    do j = 1, size(drawing%forces)
      associate (f => drawing%forces(j))
        if (f%kind /= force_pair .or. len_trim(f%name) /= 3 .or. f%name(1:1) /= "F") cycle
        if (link_index(topo, f%name(3:3)) == 0 .and. verify(f%name(3:3), "0123456789") == 0) then
          name = f%name(3:3)
          return
        end if
      end associate
    end do
  end function frame_number

  !> A group's links as the sheets write them, "2,3"; with `numbers`, by number as the
  !> structure formula writes them ("3,1,2": an &assur deck's link L1 is link 1).
  pure function group_links_text(topo, links, numbers) result(text)
    type(sketch_t), intent(in) :: topo
    integer, intent(in) :: links(:)
    logical, intent(in), optional :: numbers
    character(len=:), allocatable :: text, name
    integer :: q
    text = ""
    do q = 1, size(links)
      if (q > 1) text = text//","
      name = topo%links(links(q))%name
      if (present(numbers)) then
        if (numbers .and. name(1:1) == "L") name = name(2:)
      end if
      text = text//name
    end do
  end function group_links_text

  !> The force polygon of every unit of the structure as kinetostatics closes it, from the
  !> last group to the input units (see the module's comment for the order). A cylinder
  !> drive's cylinder and rod are one body of their group (their pair is the drive: its force
  !> and reaction cancel inside the group). A revolute pair's reaction on a link with another
  !> joint in the group is split into its tangential part (perpendicular to the line to that
  !> joint, found from the link's moments about it) and its normal part (along it).
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
    type(plan_vector_t), allocatable :: drive(:)
    type(reaction_parts_t), allocatable :: reactions(:)
    integer, allocatable :: body(:), reaction_body(:)
    type(load_list_t), allocatable :: loads(:)
    logical, allocatable :: member(:), before(:)
    integer :: gr, q, i, j, a, b, nb, crank, actuator, cylinder
    allocate (polygons(0), member(size(topo%links)), before(0:size(topo%links)), body(size(topo%links)))
    call driver_links(topo, drawing, driver, crank, actuator)
    cylinder = 0
    if (actuator > 0) cylinder = guide_link(topo, actuator)
    if (.not. allocated(drawing%forces)) return
    before = .false.
    do gr = size(groups), 1, -1
      member = .false.
      member(groups(gr)%links) = .true.
      ! the bodies: every link, the cylinder and its rod together
      body = 0
      nb = 0
      do q = 1, size(groups(gr)%links)
        i = groups(gr)%links(q)
        if (i == actuator .and. cylinder > 0) then
          if (member(cylinder) .and. body(cylinder) > 0) body(i) = body(cylinder)
        else if (i == cylinder .and. actuator > 0) then
          if (member(actuator) .and. body(actuator) > 0) body(i) = body(actuator)
        end if
        if (body(i) == 0) then
          nb = nb + 1
          body(i) = nb
        end if
      end do
      allocate (loads(nb), drive(0), reactions(0), reaction_body(0))
      do b = 1, nb
        allocate (loads(b)%v(0))
      end do
      ! the known loads of every body, link by link: weight, inertia force, external loads
      do q = 1, size(groups(gr)%links)
        i = groups(gr)%links(q)
        call body_loads(i, loads(body(i))%v, drive)
      end do
      ! the reactions on the group from the links outside it: from a group solved before
      ! (known), else unknown
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (f%kind /= force_pair .or. len_trim(f%name) /= 3 .or. f%name(1:1) /= "F") cycle
          a = link_index(topo, f%name(2:2))
          b = link_index(topo, f%name(3:3))
          if (a > 0 .and. in_group(a) .and. .not. in_group(b)) then
            call add_reaction(trim(f%name), f%f, a, b, f%at, reactions, reaction_body)
          else if (b > 0 .and. in_group(b) .and. .not. in_group(a)) then
            call add_reaction("F"//f%name(3:3)//f%name(2:2), -f%f, b, a, f%at, reactions, reaction_body)
          end if
        end associate
      end do
      poly%link = group_links_text(topo, groups(gr)%links)
      poly%label = groups(gr)%label
      poly%input = groups(gr)%input
      call order_polygon(poly)
      before(groups(gr)%links) = .true.
      poly%moment = ""
      poly%moment_value = 0.0_wp
      if (groups(gr)%input .and. allocated(groups(gr)%drive)) then
        if (table%column_index(groups(gr)%drive) > 0) then
          poly%moment = groups(gr)%drive
          poly%moment_value = column_value(table, groups(gr)%drive, k)
        end if
      end if
      poly%closure = closure_of(poly%vectors)
      polygons = [polygons, poly]
      deallocate (loads, drive, reactions, reaction_body)
    end do
  contains
    !> Whether link l (0: the frame) is of the group.
    pure logical function in_group(l)
      integer, intent(in) :: l
      in_group = .false.
      if (l > 0) in_group = member(l)
    end function in_group
    !> The known loads of link i: weight, inertia force, external loads; the reactions of the
    !> groups solved before; a drive force whose reaction is not in the same body apart.
    pure subroutine body_loads(i, v, drive)
      integer, intent(in) :: i
      type(plan_vector_t), allocatable, intent(inout) :: v(:), drive(:)
      integer :: pass, t, o
      logical :: take, inside
      do pass = 1, 3
        do t = 1, size(drawing%forces)
          associate (f => drawing%forces(t))
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
            ! a cylinder's force and its reaction inside one body cancel; else apart
            inside = actuator > 0 .and. cylinder > 0 .and. trim(f%name) == trim(driver)
            if (inside) inside = member(actuator) .and. member(cylinder) .and. body(actuator) == body(cylinder)
            ! a drive's force (or its reaction): one of the body's loads in a group of several
            ! bodies, apart (after the known reactions) in a one-body unit
            if (take .and. trim(f%name) == trim(driver)) then
              if (.not. inside .and. nb >= 2) v = [v, plan_vector_t(f%name, f%f)]
              if (.not. inside .and. nb < 2) drive = [drive, plan_vector_t(f%name, f%f)]
            else if (take) then
              v = [v, plan_vector_t(f%name, f%f)]
            end if
            if (pass == 3 .and. len_trim(f%on_link) > 0 .and. trim(f%name) == trim(driver) .and. .not. inside) then
              if (guide_link(topo, link_index(topo, trim(f%on_link))) == i) then
                if (nb >= 2) v = [v, plan_vector_t("-"//f%name, -f%f)]
                if (nb < 2) drive = [drive, plan_vector_t("-"//f%name, -f%f)]
              end if
            end if
          end associate
        end do
      end do
      do t = 1, size(drawing%forces)
        associate (f => drawing%forces(t))
          if (f%kind /= force_pair .or. len_trim(f%name) /= 3 .or. f%name(1:1) /= "F") cycle
          o = link_index(topo, f%name(3:3))
          if (link_index(topo, f%name(2:2)) == i .and. o > 0) then
            if (.not. member(o) .and. before(o)) v = [v, plan_vector_t(f%name, f%f)]
          end if
          o = link_index(topo, f%name(2:2))
          if (link_index(topo, f%name(3:3)) == i .and. o > 0) then
            if (.not. member(o) .and. before(o)) v = [v, plan_vector_t("F"//f%name(3:3)//f%name(2:2), -f%f)]
          end if
        end associate
      end do
    end subroutine body_loads
    !> The reaction `f` (N) on link l of the group from link o (0: the frame) at `at`: a
    !> known load from a group solved before, else an unknown, split when the pair is revolute
    !> and l's body has another joint with a body of the group.
    pure subroutine add_reaction(name, f, l, o, at, reactions, reaction_body)
      character(*), intent(in) :: name
      real(wp), intent(in) :: f(2), at(2)
      integer, intent(in) :: l, o
      type(reaction_parts_t), allocatable, intent(inout) :: reactions(:)
      integer, allocatable, intent(inout) :: reaction_body(:)
      type(reaction_parts_t) :: r
      integer :: s
      real(wp) :: e(2), inner(2)
      logical :: split
      if (o > 0) then
        if (before(o)) return
      end if
      call inner_joint(l, at, split, inner)
      do s = 1, size(slides)
        if ((slides(s)%m == l .and. slides(s)%g == o) .or. (slides(s)%m == o .and. slides(s)%g == l)) split = .false.
      end do
      ! a block's pin is its only joint, unless it is one body with the other half of a cylinder drive
      if (topo%links(l)%block .and. l /= actuator .and. l /= cylinder) split = .false.
      r%name = name
      r%from_moving = o > 0
      if (split) then
        e = (inner - at) / norm2(inner - at)
        r%parts = [plan_vector_t(name//"^τ", f - dot_product(f, e) * e, component_tangential), &
          plan_vector_t(name//"^n", dot_product(f, e) * e, component_normal)]
      else
        r%parts = [plan_vector_t(name, f, component_reaction)]
      end if
      reactions = [reactions, r]
      reaction_body = [reaction_body, body(l)]
    end subroutine add_reaction
    !> Whether link l's body has a joint (not at `at`) with another body of the group
    !> (`found`); its position.
    pure subroutine inner_joint(l, at, found, p)
      integer, intent(in) :: l
      real(wp), intent(in) :: at(2)
      logical, intent(out) :: found
      real(wp), intent(out) :: p(2)
      integer :: t, o, m
      found = .false.
      p = 0.0_wp
      do m = 1, size(topo%links)
        if (.not. member(m)) cycle
        if (body(m) /= body(l)) cycle
        do t = 1, size(topo%links(m)%points)
          associate (pname => topo%links(m)%points(t))
            if (drawing%point_index(trim(pname)) == 0 .or. sliding_on(topo, m, trim(pname))) cycle
            if (norm2(drawing%at(trim(pname)) - at) <= 1.0e-9_wp * (1.0_wp + norm2(at))) cycle
            do o = 1, size(topo%links)
              if (.not. member(o)) cycle
              if (body(o) == body(l)) cycle
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
    !> The polygon's vectors in the course's order, its whole and inner reactions.
    pure subroutine order_polygon(poly)
      type(force_polygon_t), intent(inout) :: poly
      integer :: first, second, r, bb, base, start, q2
      integer, allocatable :: order(:)
      poly%vectors = [plan_vector_t ::]
      poly%reactions = [plan_reaction_t ::]
      if (nb == 2) then
        ! a dyad: a is the body attached to a moving link (the first body when both or neither are)
        first = 1
        if (count(reaction_body == 2 .and. reactions%from_moving) > 0 .and. &
          count(reaction_body == 1 .and. reactions%from_moving) == 0) first = 2
        if (count(reaction_body == first) == 0) first = 3 - first
        second = 3 - first
        r = findloc(reaction_body, first, dim=1)
        if (r > 0) then
          if (size(reactions(r)%parts) == 2) call push_part(poly, r, 1)
        end if
        start = size(poly%vectors)
        call push_loads(poly, first)
        q2 = size(poly%vectors)
        call push_loads(poly, second)
        call push_reactions_of(poly, second, 0)
        call push_reactions_of(poly, first, r)
        if (r > 0) then
          call push_part(poly, r, size(reactions(r)%parts))
          call close_reaction(poly, r)
          ! the inner reaction on a from b, from a's polygon: a's reaction, loads and it close
          call push_inner(poly, first, second, q2, size(poly%vectors) - 1)
        end if
      else if (nb >= 3) then
        ! a group of a higher class: the base body joins the most bodies of the group
        base = base_body()
        allocate (order(0))
        do r = 1, size(reactions)
          if (reaction_body(r) /= base .and. .not. any(order == reaction_body(r))) order = [order, reaction_body(r)]
        end do
        do bb = 1, nb
          if (bb /= base .and. .not. any(order == bb)) order = [order, bb]
        end do
        do q2 = 1, size(order)
          bb = order(q2)
          start = size(poly%vectors)
          call push_reactions_of(poly, bb, 0)
          call push_loads(poly, bb)
          if (count(reaction_body == bb) > 0) call push_inner(poly, bb, base, size(poly%vectors), start)
        end do
        call push_loads(poly, base)
        call push_reactions_of(poly, base, 0)
      else
        ! an input unit (or a one-body group): its loads, the known reactions, the drive, the
        ! frame's reaction
        do bb = 1, nb
          call push_loads(poly, bb)
        end do
        poly%vectors = [poly%vectors, drive]
        do bb = 1, nb
          call push_reactions_of(poly, bb, 0)
        end do
      end if
    end subroutine order_polygon
    !> The loads (and known reactions) of body bb.
    pure subroutine push_loads(poly, bb)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: bb
      poly%vectors = [poly%vectors, loads(bb)%v]
    end subroutine push_loads
    !> Every unknown reaction of body bb (but reaction `skip`) with its parts together.
    pure subroutine push_reactions_of(poly, bb, skip)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: bb, skip
      integer :: t, q
      do t = 1, size(reactions)
        if (reaction_body(t) /= bb .or. t == skip) cycle
        call open_reaction(poly, t)
        do q = 1, size(reactions(t)%parts)
          poly%vectors = [poly%vectors, reactions(t)%parts(q)]
        end do
        call close_reaction(poly, t)
      end do
    end subroutine push_reactions_of
    !> Part q of reaction t (the first opens its whole reaction's record).
    pure subroutine push_part(poly, t, q)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: t, q
      if (q == 1) call open_reaction(poly, t)
      poly%vectors = [poly%vectors, reactions(t)%parts(q)]
    end subroutine push_part
    !> The whole reaction t starts at the polygon's present vertex.
    pure subroutine open_reaction(poly, t)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: t
      real(wp) :: whole(2)
      integer :: q
      whole = 0.0_wp
      do q = 1, size(reactions(t)%parts)
        whole = whole + reactions(t)%parts(q)%v
      end do
      poly%reactions = [poly%reactions, plan_reaction_t(reactions(t)%name, whole, .false., size(poly%vectors), -1)]
    end subroutine open_reaction
    !> The whole reaction t ends at the polygon's present vertex (split around the start: its
    !> last part closes the polygon, its first opened it - the whole from the last part's
    !> tail to the first part's head).
    pure subroutine close_reaction(poly, t)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: t
      integer :: q
      do q = 1, size(poly%reactions)
        if (poly%reactions(q)%name /= reactions(t)%name .or. poly%reactions(q)%head /= -1) cycle
        poly%reactions(q)%head = size(poly%vectors)
        if (poly%reactions(q)%tail /= 0 .or. size(reactions(t)%parts) /= 2 .or. size(poly%vectors) <= 2) cycle
        if (poly%vectors(1)%name == reactions(t)%parts(1)%name .and. &
          poly%vectors(size(poly%vectors))%name == reactions(t)%parts(2)%name) then
          poly%reactions(q)%tail = size(poly%vectors) - 1
          poly%reactions(q)%head = 1
        end if
      end do
    end subroutine close_reaction
    !> The inner reaction on body ba from body bo, found from ba's polygon: drawn from the
    !> vertex `tail` (after ba's loads) to the vertex `head` (where ba's reaction starts).
    pure subroutine push_inner(poly, ba, bo, tail, head)
      type(force_polygon_t), intent(inout) :: poly
      integer, intent(in) :: ba, bo, tail, head
      real(wp), allocatable :: tips(:, :)
      integer :: t
      allocate (tips(2, 0:size(poly%vectors)))
      tips(:, 0) = 0.0_wp
      do t = 1, size(poly%vectors)
        tips(:, t) = tips(:, t - 1) + poly%vectors(t)%v
      end do
      poly%reactions = [poly%reactions, plan_reaction_t(inner_name(ba, bo), tips(:, head) - tips(:, tail), .true., &
        tail, head)]
    end subroutine push_inner
    !> The name F<on><from> of the pair between bodies ba and bo (the table's pair force, or
    !> the two bodies' first links).
    pure function inner_name(ba, bo) result(name)
      integer, intent(in) :: ba, bo
      character(len=16) :: name
      integer :: t, x, y
      name = "F"//link_digits(first_link(ba))//link_digits(first_link(bo))
      do t = 1, size(drawing%forces)
        call group_pair(t, x, y)
        if (x == 0) cycle
        associate (f => drawing%forces(t))
          if (body(x) == ba .and. body(y) == bo) name = f%name
          if (body(x) == bo .and. body(y) == ba) name = "F"//f%name(3:3)//f%name(2:2)
        end associate
      end do
    end function inner_name
    !> The first link (in the group's order) of body bb.
    pure integer function first_link(bb)
      integer, intent(in) :: bb
      integer :: t
      first_link = 0
      do t = size(groups(gr)%links), 1, -1
        if (body(groups(gr)%links(t)) == bb) first_link = groups(gr)%links(t)
      end do
    end function first_link
    !> A link's number as a pair force names it ("L1" -> "1").
    pure function link_digits(l) result(text)
      integer, intent(in) :: l
      character(len=:), allocatable :: text
      text = "?"
      if (l == 0) return
      text = topo%links(l)%name
      if (text(1:1) == "L") text = text(2:)
    end function link_digits
    !> The body sharing joints with the most other bodies of the group.
    pure integer function base_body()
      integer :: bb, o, y, t, best, joins
      logical, allocatable :: joined(:)
      base_body = 1
      best = -1
      allocate (joined(nb))
      do bb = 1, nb
        joined = .false.
        do t = 1, size(drawing%forces)
          call group_pair(t, o, y)
          if (o == 0) cycle
          if (body(o) == bb .and. body(y) /= bb) joined(body(y)) = .true.
          if (body(y) == bb .and. body(o) /= bb) joined(body(o)) = .true.
        end do
        joins = count(joined)
        if (joins > best) then
          best = joins
          base_body = bb
        end if
      end do
    end function base_body
    !> The links x, y of the drawing's force t when it is a pair force F<x><y> between two
    !> links of the group; else 0, 0.
    pure subroutine group_pair(t, x, y)
      integer, intent(in) :: t
      integer, intent(out) :: x, y
      x = 0
      y = 0
      associate (f => drawing%forces(t))
        if (f%kind /= force_pair .or. len_trim(f%name) /= 3 .or. f%name(1:1) /= "F") return
        x = link_index(topo, f%name(2:2))
        y = link_index(topo, f%name(3:3))
      end associate
      if (x > 0 .and. y > 0) then
        if (member(x) .and. member(y)) return
      end if
      x = 0
      y = 0
    end subroutine group_pair
  end subroutine group_polygons_of

  !> The force polygon of every link: its loads (weight, inertia force, external loads), then
  !> the pair forces on it (F<L><j> as written, F<j><L> reversed).
  pure subroutine link_polygons_of(topo, drawing, driver, polygons)
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
      poly%label = ""
      poly%moment = ""
      allocate (poly%vectors(0), poly%reactions(0))
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
      deallocate (poly%vectors, poly%reactions)
    end do
  end subroutine link_polygons_of

end module kinetostat_plans_groups
