!> An Assur group drawn apart, as the course draws it before the force polygon (the course
!> sheet "kinetostatics"): the group's links at a scale of their own with their joints
!> lettered; the loads on them (G, Φ, the external loads, the inertia couples); the unknown
!> reactions at the outer pairs as the polygon gives them (split into τ and n where the polygon
!> splits them, whole otherwise) at their pairs' points; and, for every link with one inner
!> joint (a joint with another link of the group), the arm h of every force of that link about
!> the inner joint (dashed, named h_G2, h_Φ2, h34 ...), with a table of the arms in mm at the
!> drawing's μl. Each link's moment equation is attached to its group (data-link, data-about,
!> data-mu-l; every arm data-force, data-h, data-sense) so that a check recomputes R^τ from the
!> drawing's numbers.
module kinetostat_plans_apart
  use kinetostat_kinds, only: wp, pi
  use kinetostat_format, only: short_number, full_number
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_scales, only: scale_number
  use kinetostat_sheet, only: sheet_t, layer_polygons, layer_text, class_font_size
  use kinetostat_drawing, only: drawing_t, drawing_force_t, point_pivot, point_joint
  use kinetostat_mechanism_view, only: mechanism_view_t, draw_mechanism, mark_other_drawing
  use kinetostat_plans_base, only: plans_t, owner, component_reaction, component_tangential
  implicit none
  private
  public :: group_apart_drawing, draw_group_apart, guide_reactions_placed

  !> An arm shorter than this on the drawing is not drawn (its force passes through the
  !> joint), mm.
  real(wp), parameter :: shortest = 0.5_wp
  character(*), parameter :: arm_colour = "#555555"
  !> Pitch of the arms' table's rows under the group, mm.
  real(wp), parameter, public :: row_pitch = 2.7_wp

contains

  !> Whether `link` is one of the group's links (`links`: "2,3").
  pure logical function in_group(links, link)
    character(*), intent(in) :: links, link
    in_group = index(","//trim(links)//",", ","//trim(link)//",") > 0 .and. len_trim(link) > 0
  end function in_group

  !> The link a polygon's vector acts on: G2, Phi2 -> 2; F21, F21^τ -> 2; a load by the
  !> drawing's on_link ("" when unknown): the owner of the vector, a pair force's part
  !> counted as the pair force.
  pure function acted_link(name, on_link) result(link)
    character(*), intent(in) :: name, on_link
    character(len=:), allocatable :: link
    link = owner(pair_base(name), on_link)
  end function acted_link

  !> Whether a name is a pair's reaction F<on><from> (its part ^τ, ^n after it).
  pure logical function is_pair(name)
    character(*), intent(in) :: name
    character(len=:), allocatable :: base
    base = pair_base(name)
    is_pair = .false.
    if (len(base) == 3) is_pair = base(1:1) == "F" .and. verify(base(2:3), "0123456789") == 0
  end function is_pair

  !> A reaction's name without its part: F21^τ -> F21.
  pure function pair_base(name) result(base)
    character(*), intent(in) :: name
    character(len=:), allocatable :: base
    integer :: hat
    hat = index(name, "^")
    if (hat > 0) then
      base = trim(name(:hat - 1))
    else
      base = trim(name)
    end if
  end function pair_base

  !> Group `e`'s links apart (points in metres, as the mechanism's drawing has them): its
  !> bodies and points, every vector of its polygon as a force at its point (the polygon's
  !> value), its links' moments; `inner(q)` the index in link%points of link q's only inner
  !> joint (0: none or more than one), `names(q)` the group's links.
  pure subroutine group_apart_drawing(drawing, plans, e, link, names, inner, unknown, pivots, sources, shift)
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: e
    type(drawing_t), intent(out) :: link
    character(len=16), allocatable, intent(out) :: names(:)
    integer, allocatable, intent(out) :: inner(:)
    !> Whether link%forces(j) is an unknown reaction of the polygon (whole or its τ part).
    logical, allocatable, intent(out), optional :: unknown(:)
    !> link%points' indices of the group's pivots on the frame.
    integer, allocatable, intent(out), optional :: pivots(:)
    !> The index in drawing%forces of each of link%forces, and the shift of the group's
    !> points from the drawing's (link's point = drawing's point - shift), m.
    integer, allocatable, intent(out), optional :: sources(:)
    real(wp), intent(out), optional :: shift(2)
    integer, allocatable :: source(:)
    character(len=:), allocatable :: links, base
    integer :: j, q, i, p, found, shared
    real(wp) :: at(2), total, u(2), c
    integer :: k, jj, only
    logical, allocatable :: open(:)
    allocate (link%points(0), link%bodies(0), link%guides(0), link%forces(0), link%moments(0), names(0), open(0), &
      source(0))
    link%view_angle = drawing%view_angle
    links = trim(plans%group_polygons(e)%link)
    do j = 1, size(drawing%bodies)
      if (.not. in_group(links, drawing%bodies(j)%name)) cycle
      if (.not. any(names == drawing%bodies(j)%name)) names = [character(len=16) :: names, drawing%bodies(j)%name]
      link%bodies = [link%bodies, drawing%bodies(j)]
      do q = 1, size(drawing%bodies(j)%points)
        p = 0
        do i = 1, size(link%points)
          if (link%points(i)%name == drawing%points(drawing%bodies(j)%points(q))%name) p = i
        end do
        if (p == 0) then
          link%points = [link%points, drawing%points(drawing%bodies(j)%points(q))]
          p = size(link%points)
        end if
        link%bodies(size(link%bodies))%points(q) = p
      end do
    end do
    ! each link's inner joint: its point that another body of the group holds
    allocate (inner(size(names)))
    inner = 0
    do q = 1, size(names)
      shared = 0
      do j = 1, size(link%bodies)
        if (link%bodies(j)%name /= names(q)) cycle
        do i = 1, size(link%bodies(j)%points)
          p = link%bodies(j)%points(i)
          if (held_elsewhere(p, names(q))) then
            if (inner(q) /= p) shared = shared + 1
            inner(q) = p
          end if
        end do
      end do
      if (shared /= 1) inner(q) = 0
    end do
    ! the polygon's vectors at their points
    associate (poly => plans%group_polygons(e))
      do j = 1, size(poly%vectors)
        base = pair_base(poly%vectors(j)%name)
        found = 0
        do i = 1, size(drawing%forces)
          if (drawing%forces(i)%name == base) found = i
          if (found == 0 .and. is_pair(base)) then
            if (drawing%forces(i)%name == "F"//base(3:3)//base(2:2)) found = i
          end if
        end do
        if (found == 0) cycle
        at = drawing%forces(found)%at
        link%forces = [link%forces, drawing_force_t(poly%vectors(j)%name, drawing%forces(found)%kind, at, &
          poly%vectors(j)%v, acted_link(poly%vectors(j)%name, drawing%forces(found)%on_link))]
        source = [source, found]
        open = [open, poly%vectors(j)%kind == component_reaction .or. poly%vectors(j)%kind == component_tangential]
      end do
    end associate
    do j = 1, size(drawing%moments)
      associate (m => drawing%moments(j))
        do q = 1, size(names)
          if (trim(m%on_link) == trim(names(q)) .or. m%name == "M"//trim(names(q)) .or. &
            m%name == "MPhi"//trim(names(q))) then
            link%moments = [link%moments, m]
            link%moments(size(link%moments))%on_link = names(q)
          end if
        end do
      end associate
    end do
    ! A link with one inner joint whose moment equation about it has one unknown, a whole
    ! reaction of a guide on the frame (a slider's normal reaction, which the run gives no
    ! line of action): its point of application shifted along the guide (square to the
    ! force) so that the link's moments about the joint balance, as the course finds it.
    do k = 1, size(names)
      if (inner(k) == 0) cycle
      only = 0
      total = 0.0_wp
      do jj = 1, size(link%forces)
        if (trim(link%forces(jj)%on_link) /= trim(names(k))) cycle
        if (open(jj)) then
          if (only /= 0 .or. .not. frame_reaction(link%forces(jj)%name) .or. at_joint(link%forces(jj)%at)) then
            only = -1
            exit
          end if
          only = jj
        end if
        associate (r => link%forces(jj)%at - link%points(inner(k))%p, f => link%forces(jj)%f)
          total = total + r(1) * f(2) - r(2) * f(1)
        end associate
      end do
      if (only <= 0) cycle
      do jj = 1, size(link%moments)
        if (trim(link%moments(jj)%on_link) == trim(names(k))) total = total + link%moments(jj)%value
      end do
      associate (f => link%forces(only)%f)
        if (norm2(f) <= 0.0_wp) cycle
        u = [f(2), -f(1)] / norm2(f)
        c = u(1) * f(2) - u(2) * f(1)
        link%forces(only)%at = link%forces(only)%at - total / c * u
      end associate
    end do
    if (present(unknown)) unknown = open
    if (present(pivots)) pivots = pack([(i, i = 1, size(link%points))], link%points%kind == point_pivot)
    if (present(sources)) sources = source
    if (present(shift)) shift = 0.0_wp
    ! the outer joints drawn as joints (not the frame's pivots); the group shifted so that the
    ! position frame's origin (its axes) lies on an inner joint, or on its first point
    where (link%points%kind == point_pivot) link%points%kind = point_joint
    p = 1
    if (any(inner > 0)) p = maxval(inner)
    if (size(link%points) == 0) return
    at = link%points(p)%p
    if (present(shift)) shift = at
    call link%move_points_and_loads(-at)
  contains
    !> Whether `at` is a pivot on the frame or a joint two of the group's links hold (a
    !> reaction there has its line through it).
    pure logical function at_joint(at)
      real(wp), intent(in) :: at(2)
      integer :: m, holders, bb
      at_joint = .false.
      do m = 1, size(link%points)
        if (norm2(link%points(m)%p - at) > 1.0e-12_wp) cycle
        holders = 0
        do bb = 1, size(link%bodies)
          if (any(link%bodies(bb)%points == m)) holders = holders + 1
        end do
        if (link%points(m)%kind == point_pivot .or. holders > 1) at_joint = .true.
      end do
    end function at_joint
    !> F<link><frame>: a reaction of the frame (the frame's digit the largest of the deck's).
    pure logical function frame_reaction(name)
      character(*), intent(in) :: name
      frame_reaction = .false.
      if (len_trim(name) /= 3 .or. name(1:1) /= "F") return
      if (verify(name(2:3), "0123456789") /= 0) return
      frame_reaction = .not. any(names == name(3:3))
    end function frame_reaction
    pure logical function held_elsewhere(p, name)
      integer, intent(in) :: p
      character(*), intent(in) :: name
      integer :: b
      held_elsewhere = .false.
      do b = 1, size(link%bodies)
        if (link%bodies(b)%name == name) cycle
        if (any(link%bodies(b)%points == p)) held_elsewhere = .true.
      end do
    end function held_elsewhere
  end subroutine group_apart_drawing

  !> The mechanism's drawing with every whole reaction of a guide on the frame that a group
  !> drawn apart places on its line of action (group_apart_drawing: a slider's normal
  !> reaction, at the arm its link's moment equation gives) at that point; `moved(j)` whether
  !> drawing%forces(j) moved, `from(:, j)` its point before, m.
  pure subroutine guide_reactions_placed(drawing, plans, placed, moved, from)
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    type(drawing_t), intent(out) :: placed
    logical, allocatable, intent(out) :: moved(:)
    real(wp), allocatable, intent(out) :: from(:, :)
    type(drawing_t) :: link
    character(len=16), allocatable :: names(:)
    integer, allocatable :: inner(:), sources(:)
    real(wp) :: shift(2), at(2)
    integer :: e, j, k
    placed = drawing
    allocate (moved(size(drawing%forces)), from(2, size(drawing%forces)))
    moved = .false.
    do j = 1, size(drawing%forces)
      from(:, j) = drawing%forces(j)%at
    end do
    do e = 1, size(plans%group_polygons)
      if (plans%group_polygons(e)%input) cycle
      call group_apart_drawing(drawing, plans, e, link, names, inner, sources=sources, shift=shift)
      do j = 1, size(link%forces)
        k = sources(j)
        if (k <= 0 .or. trim(link%forces(j)%name) /= trim(drawing%forces(k)%name)) cycle
        at = link%forces(j)%at + shift
        if (norm2(at - drawing%forces(k)%at) <= 1.0e-9_wp * max(1.0_wp, norm2(at))) cycle
        placed%forces(k)%at = at
        moved(k) = .true.
      end do
    end do
  end subroutine guide_reactions_placed

  !> Group e drawn apart in `box` at `view` (forces `per_newton` mm/N), with the arms about
  !> each link's inner joint and their table from `table_at`.
  pure subroutine draw_group_apart(sheet, drawing, plans, e, view, box, per_newton, lang, table_at)
    type(sheet_t), intent(inout) :: sheet
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: e, lang
    type(mechanism_view_t), intent(in) :: view
    real(wp), intent(in) :: box(4), per_newton
    !> The arms' table's first row (x, y), mm (0, 0: no table).
    real(wp), intent(in) :: table_at(2)
    type(drawing_t) :: link
    character(len=16), allocatable :: names(:)
    integer, allocatable :: inner(:)
    character(len=:), allocatable :: short, line, arm
    character(len=80), allocatable :: rows(:)
    real(wp) :: a(2), tail(2), tip(2), d(2), foot(2), h, sense, mu_l, area(4), label_size
    real(wp), allocatable :: lx(:), ly(:), lang_angle(:)
    character(len=16), allocatable :: lname(:)
    integer :: j, q, first, k, n_eq, about, sought
    logical, allocatable :: unknown(:)
    integer, allocatable :: pivots(:)
    character(len=:), allocatable :: label
    real(wp) :: total, sought_h
    call group_apart_drawing(drawing, plans, e, link, names, inner, unknown, pivots)
    mu_l = view%mu_l()
    area = box
    allocate (rows(0), lx(0), ly(0), lang_angle(0), lname(0))
    call sheet%set_layer(layer_polygons)
    ! the moment equations: the arms about each link's inner joint first (labels keep off them);
    ! a group without one (a sliding inner pair: the block between the links) about its
    ! pivot on the frame, the whole group's forces (the massless block passes its reaction on)
    n_eq = count(inner > 0)
    if (n_eq == 0 .and. size(pivots) > 0) n_eq = 1
    do k = 1, n_eq
      if (count(inner > 0) == 0) then
        about = pivots(1)
        label = trim(plans%group_polygons(e)%link)
      else
        q = 0
        do j = 1, size(names)
          if (inner(j) > 0) q = q + 1
          if (q == k) exit
        end do
        about = inner(j)
        label = trim(names(j))
      end if
      a = view%point(link%points(about)%p)
      call sheet%group("moment-equation")
      call sheet%attach("data-link", label)
      call sheet%attach("data-about", trim(link%points(about)%name))
      call sheet%attach("data-mu-l", full_number(mu_l))
      line = "Σ M_"//trim(link%points(about)%name)//"("//label//") = 0:"
      rows = [character(len=80) :: rows, line]
      sought = 0
      total = 0.0_wp
      do j = 1, size(link%forces)
        if (.not. member(link%forces(j)%on_link)) cycle
        if (norm2(link%forces(j)%f) <= 0.0_wp) cycle
        tail = view%point(link%forces(j)%at)
        ! the force's direction on the sheet (a unit vector; the view turns, flips y)
        tip = view%point(link%forces(j)%at + 1.0e-3_wp * link%forces(j)%f / norm2(link%forces(j)%f))
        d = (tip - tail) / norm2(tip - tail)
        foot = tail + dot_product(a - tail, d) * d
        h = norm2(foot - a)
        ! the moment's sense about the joint, in the position frame (counterclockwise +)
        associate (r => link%forces(j)%at - link%points(about)%p, f => link%forces(j)%f)
          sense = sign(1.0_wp, r(1) * f(2) - r(2) * f(1))
        end associate
        if (h < shortest) then
          sense = 0.0_wp
          h = 0.0_wp
        end if
        arm = arm_name(trim(link%forces(j)%name), lang)
        call sheet%group("arm")
        call sheet%attach("data-arm", arm)
        call sheet%attach("data-force-name", trim(link%forces(j)%name))
        call sheet%attach("data-force", full_number(norm2(link%forces(j)%f)))
        call sheet%attach("data-h", full_number(h))
        call sheet%attach("data-sense", full_number(sense))
        ! the unknown of the equation: the reaction's τ part (or whole, its line known) or, a
        ! guide's reaction, its arm
        if (unknown(j) .and. h >= shortest) then
          sought = j
          sought_h = h
          call sheet%attach("data-unknown", merge("arm  ", "force", frame_force(link%forces(j)%name)))
        else
          total = total + sense * norm2(link%forces(j)%f) * h * mu_l
        end if
        if (h >= shortest) then
          call sheet%line(a(1), a(2), foot(1), foot(2), stroke=arm_colour, width=0.15_wp, dash="1 0.8")
          call sheet%line(tail(1), tail(2), foot(1), foot(2), stroke=arm_colour, width=0.1_wp, dash="0.4 0.6")
          lx = [lx, 0.5_wp * (a(1) + foot(1))]
          ly = [ly, 0.5_wp * (a(2) + foot(2))]
          lang_angle = [lang_angle, atan2(foot(2) - a(2), foot(1) - a(1)) - 0.5_wp * pi]
          lname = [character(len=16) :: lname, arm]
          rows = [character(len=80) :: rows, "  "//arm//" = "//short_number(h)//" "//unit_word("mm", lang)// &
            ", "//display(trim(link%forces(j)%name), lang)//" = "//short_number(norm2(link%forces(j)%f))//" "// &
            unit_word("N", lang)//": "//short_number(sense * norm2(link%forces(j)%f) * h * mu_l)//" "// &
            unit_word("N*m", lang)]
        else
          rows = [character(len=80) :: rows, "  "//display(trim(link%forces(j)%name), lang)//": "// &
            word("through the joint", lang)]
        end if
        call sheet%end_group()
      end do
      do j = 1, size(link%moments)
        if (.not. member(link%moments(j)%on_link)) cycle
        call sheet%group("arm")
        call sheet%attach("data-moment-name", trim(link%moments(j)%name))
        call sheet%attach("data-moment", full_number(link%moments(j)%value))
        call sheet%end_group()
        total = total + link%moments(j)%value
        rows = [character(len=80) :: rows, "  "//display(trim(link%moments(j)%name), lang)//" = "// &
          short_number(link%moments(j)%value)//" "//unit_word("N*m", lang)]
      end do
      ! the unknown from the equation: |Σ of the others| / h μl (a force) or / F (an arm)
      if (sought > 0) then
        if (frame_force(link%forces(sought)%name)) then
          rows = [character(len=80) :: rows, "  → "//arm_name(trim(link%forces(sought)%name), lang)//" = |Σ| / "// &
            display(trim(link%forces(sought)%name), lang)//" = "//short_number(abs(total) / &
            norm2(link%forces(sought)%f) / mu_l)//" "//unit_word("mm", lang)]
        else
          rows = [character(len=80) :: rows, "  → "//display(trim(link%forces(sought)%name), lang)//" = |Σ| / "// &
            arm_name(trim(link%forces(sought)%name), lang)//" = "//short_number(abs(total) / (sought_h * mu_l))// &
            " "//unit_word("N", lang)]
        end if
      end if
      call sheet%end_group()
    end do
    first = sheet%count + 1
    ! (A4: a group's room under 70 mm wide, its labels and arms' names at 1.8 mm, the least
    ! legible size)
    label_size = merge(1.8_wp, class_font_size("num"), area(3) - area(1) < 70.0_wp)
    if (area(3) - area(1) < 70.0_wp) then
      call draw_mechanism(sheet, link, view, area, per_newton, short, label_size=label_size)
    else
      call draw_mechanism(sheet, link, view, area, per_newton, short)
    end if
    call mark_other_drawing(sheet, first, "group-apart", "apart")
    call sheet%set_layer(layer_text)
    do j = 1, size(lname)
      call sheet%place_label(trim(lname(j)), "num", lx(j), ly(j), lang_angle(j), area, colour=arm_colour, &
        size=label_size)
    end do
    call sheet%text(box(1), box(2) - 1.5_wp, word("the group apart", lang)//", μl = "//scale_number(mu_l)//" "// &
      unit_word("m", lang)//"/"//unit_word("mm", lang), "small")
    ! the arms' table (none where table_at is 0: no room)
    if (table_at(2) <= 0.0_wp) return
    do j = 1, size(rows)
      call sheet%text(table_at(1), table_at(2) + row_pitch * (j - 1), trim(rows(j)), "small", size=1.8_wp)
    end do
  contains
    !> Whether a force or a moment on link `on` is in the equation `label` (a link or the group).
    pure logical function member(on)
      character(*), intent(in) :: on
      member = trim(on) == label .or. (in_group(label, on) .and. index(label, ",") > 0)
    end function member
    !> A reaction of the frame on the group (a guide's, its line found by the equation).
    pure logical function frame_force(name)
      character(*), intent(in) :: name
      frame_force = .false.
      if (len_trim(name) /= 3 .or. name(1:1) /= "F") return
      if (verify(name(2:3), "0123456789") /= 0) return
      frame_force = .not. any(names == name(3:3)) .and. .not. in_group(trim(plans%group_polygons(e)%link), name(3:3)) &
        .and. count(inner > 0) > 0
    end function frame_force
    pure function arm_name(force, lang) result(name)
      character(*), intent(in) :: force
      integer, intent(in) :: lang
      character(len=:), allocatable :: name, base
      if (is_pair(force)) then
        base = pair_base(force)
        name = "h"//base(2:)
        if (index(force, "^") > 0) name = name//force(index(force, "^"):)
      else
        name = "h_"//display(force, lang)
      end if
    end function arm_name
    !> The name as the polygon writes it (the typesetter makes Phi Φ, ^τ a superscript).
    pure function display(name, lang) result(text)
      character(*), intent(in) :: name
      integer, intent(in) :: lang
      character(len=:), allocatable :: text
      text = trim(name)
      if (lang < 0) text = ""
    end function display
  end subroutine draw_group_apart

end module kinetostat_plans_apart
