!> Zhukovsky's lever as the course draws it: the velocity plan turned by 90 deg, every load of
!> the step's equation at the velocity image of its point - weights, inertia forces,
!> external loads, a second drive's effort, the flywheel's inertia moment in the true motion,
!> the pairs' friction actions - an inertia (or any) moment as its couple of forces F = M/l
!> at the images of two points of its link, l apart; the balancing force P_bal at the image
!> of the driving link's pin, perpendicular to the link (M = P_bal l), or for a cylinder
!> drive the pair of its force and reaction at the two bodies' images of the same point.
!> The lever's moment of a force about the pole is minus its power, so the lever's equation
!> is the power balance of the step: the balancing effort = -(sum of the loads' powers) /
!> the driver's rate.
module kinetostat_plans_lever
  use kinetostat_kinds, only: wp
  use kinetostat_text, only: lower
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_pair
  use kinetostat_plans_base, only: plans_t, lever_load_t, lever_friction_t, load_force, load_moment, field, perp, &
    link_index, lists, sliding_on, guide_link, owner, pivot_of, coincident, slides_of, slide_t, point_velocity
  implicit none
  private
  public :: lever_of

contains

  !> Zhukovsky's lever of row k: the loads, the balancing effort -(sum of their powers) over
  !> the driver's rate (the driving link's omega; for a driving force between a slider and
  !> its guide's link, the relative velocity along the force) and the balancing force.
  !> `omega` and `v0` are the links' angular velocities and velocity fields' terms.
  pure subroutine lever_of(topo, drawing, table, k, omega, v0, plans)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    real(wp), intent(in) :: omega(:), v0(:, :)
    type(plans_t), intent(inout) :: plans
    real(wp) :: rate, unit_force(2), power, at(2)
    integer :: j, l, d, g, c, act, a, b
    type(lever_load_t) :: load
    type(slide_t), allocatable :: slides(:)
    plans%driver = ""
    if (allocated(table%driver)) plans%driver = table%driver
    plans%lever_known = .false.
    plans%lever_note = ""
    allocate (plans%loads(0))
    if (table%column_index(plans%driver) == 0) then
      plans%lever_note = "no driver column"
      return
    end if
    plans%run = table%rows(table%column_index(plans%driver), k)
    d = 0
    do j = 1, size(drawing%moments)
      if (drawing%moments(j)%name == plans%driver) d = link_index(topo, owner(drawing%moments(j)%name, &
        drawing%moments(j)%on_link))
    end do
    ! or a force between a slider and its guide's link (a hydraulic cylinder): its power is
    ! F . (v_slider - v_guide), the same at every point of the slider
    rate = 0.0_wp
    act = 0
    g = 0
    unit_force = 0.0_wp
    if (d == 0) then
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (f%name /= plans%driver .or. f%kind == force_pair .or. plans%run == 0.0_wp) cycle
          l = link_index(topo, owner(f%name, f%on_link))
          if (l == 0) cycle
          g = guide_link(topo, l)
          if (g == 0) cycle
          act = j
          unit_force = f%f / plans%run
          rate = dot_product(unit_force, velocity(l, f%at) - velocity(g, f%at))
        end associate
      end do
      if (act == 0) then
        plans%lever_note = "the driver is neither a moment on a link nor a force on a slider of the drawing"
        return
      end if
      plans%lever_rate_name = "v_rel"
    else
      rate = omega(d)
      plans%lever_rate_name = "omega"//trim(topo%links(d)%name)
    end if
    if (rate == 0.0_wp) then
      plans%lever_note = "the driving link is at rest"
      return
    end if
    plans%lever_rate = rate
    ! the forces: weights, inertia forces, external loads
    do j = 1, size(drawing%forces)
      associate (f => drawing%forces(j))
        if (f%kind == force_pair .or. f%name == plans%driver) cycle
        l = link_index(topo, owner(f%name, f%on_link))
        if (l == 0) then
          plans%lever_note = "force "//trim(f%name)//" belongs to no known link"
          return
        end if
        plans%loads = [plans%loads, force_load(trim(f%name), f%f, f%at, l, f%kind)]
      end associate
    end do
    ! the moments (inertia moments, external moments, a second drive's effort) as couples
    do j = 1, size(drawing%moments)
      if (drawing%moments(j)%name == plans%driver) cycle
      l = link_index(topo, owner(drawing%moments(j)%name, drawing%moments(j)%on_link))
      if (l == 0) then
        plans%lever_note = "moment "//trim(drawing%moments(j)%name)//" belongs to no known link"
        return
      end if
      plans%loads = [plans%loads, moment_load(trim(drawing%moments(j)%name), drawing%moments(j)%value, l, drawing%moments(j)%kind)]
    end do
    ! the true motion: the flywheel and the rotor on the driving link's shaft, -J eps on it
    if (d > 0 .and. table%dynamics%present) then
      c = table%column_index("eps"//trim(topo%links(d)%name))
      if (c > 0) then
        plans%lever_flywheel = .true.
        plans%flywheel_inertia = table%shaft_inertia()
        plans%flywheel_moment = -plans%flywheel_inertia * table%rows(c, k)
        plans%loads = [plans%loads, moment_load("M_fw", plans%flywheel_moment, d, 0)]
      end if
    end if
    call pair_friction_of(plans)
    if (len(plans%lever_note) > 0) return
    do j = 1, size(plans%friction)
      associate (pf => plans%friction(j))
        a = link_index(topo, trim(pf%on))
        b = link_index(topo, trim(pf%from))
        if (pf%prismatic .and. any(pf%force /= 0.0_wp)) then
          if (a > 0) plans%loads = [plans%loads, force_load("Ff"//trim(pf%on)//trim(pf%from), pf%force, pf%at, a, 0)]
          if (b > 0) plans%loads = [plans%loads, force_load("Ff"//trim(pf%from)//trim(pf%on), -pf%force, pf%at, b, 0)]
        else if (.not. pf%prismatic .and. pf%moment /= 0.0_wp) then
          if (a > 0) plans%loads = [plans%loads, moment_load("Mf"//trim(pf%on)//trim(pf%from), pf%moment, a, 0)]
          if (b > 0) plans%loads = [plans%loads, moment_load("Mf"//trim(pf%from)//trim(pf%on), -pf%moment, b, 0)]
        end if
      end associate
    end do
    power = 0.0_wp
    do j = 1, size(plans%loads)
      power = power + plans%loads(j)%power
    end do
    plans%friction_share = -plans%friction_power / rate
    plans%effort = -power / rate
    plans%lever_known = .true.
    ! the balancing force: at the driving link's pin, perpendicular to it; or the cylinder's
    ! force and its reaction
    if (d > 0) then
      call balancing_at_pin(d, load, plans%balancing_length)
    else
      associate (f => drawing%forces(act))
        l = link_index(topo, owner(f%name, f%on_link))
        ! the pair of the force and its reaction at the sliding pair's point (B on the rod, B1
        ! on the cylinder): the same power at every point, the links turning together
        at = f%at
        call slides_of(topo, drawing, table, k, slides)
        do j = 1, size(slides)
          if ((slides(j)%m == l .and. slides(j)%g == g) .or. (slides(j)%m == g .and. slides(j)%g == l)) at = slides(j)%p
        end do
        load = lever_load_t(name=plans%driver, kind=load_force, value=abs(plans%effort), f=plans%effort * unit_force, &
          points=[character(len=16) :: point_at(l, at), point_at(g, at)], at=velocity(l, at), at2=velocity(g, at), &
          image=image_name(l, at, plans%driver)//","//image_name(g, at, plans%driver), pair=.true., &
          link=topo%links(l)%name)
        load%power = dot_product(load%f, load%at - load%at2)
        if (load%value > 0.0_wp) load%arm = abs(load%power) / load%value
      end associate
    end if
    plans%balancing = load
  contains
    !> Velocity of the point p carried by link l (0: the frame), m/s.
    pure function velocity(l, p) result(v)
      integer, intent(in) :: l
      real(wp), intent(in) :: p(2)
      real(wp) :: v(2)
      v = point_velocity(v0, omega, l, p)
    end function velocity
    !> A force f (N) at p (m) on link l.
    pure function force_load(name, f, p, l, source) result(item)
      character(*), intent(in) :: name
      real(wp), intent(in) :: f(2), p(2)
      integer, intent(in) :: l, source
      type(lever_load_t) :: item
      item%name = name
      item%kind = load_force
      item%value = norm2(f)
      item%f = f
      item%points(1) = point_at(l, p)
      item%at = velocity(l, p)
      item%image = image_name(l, p, name)
      item%power = dot_product(f, item%at)
      if (item%value > 0.0_wp) item%arm = abs(item%power) / item%value
      item%source = source
      item%link = topo%links(l)%name
    end function force_load
    !> A moment m (N*m) on link l as its couple: F = m/l^2 (P1 - P2) turned by 90 deg at P1,
    !> -F at P2, the link's two points farthest apart.
    pure function moment_load(name, m, l, source) result(item)
      character(*), intent(in) :: name
      real(wp), intent(in) :: m
      integer, intent(in) :: l, source
      type(lever_load_t) :: item
      real(wp) :: p1(2), p2(2)
      character(len=16) :: n1, n2
      item%name = name
      item%kind = load_moment
      item%value = m
      item%source = source
      item%link = topo%links(l)%name
      item%pair = .true.
      call couple_points(l, n1, n2, p1, p2)
      item%points = [n1, n2]
      item%l = norm2(p1 - p2)
      item%at = velocity(l, p1)
      item%at2 = velocity(l, p2)
      item%image = image_name(l, p1, name)//","//image_name(l, p2, name)
      if (item%l > 0.0_wp) then
        item%f = m / item%l**2 * perp(p1 - p2)
        item%power = dot_product(item%f, item%at - item%at2)
        if (norm2(item%f) > 0.0_wp) item%arm = abs(item%power) / norm2(item%f)
      else
        ! no two points: the moment's power as it is (m omega), not drawn as a couple
        item%power = m * omega(l)
        item%pair = .false.
      end if
    end function moment_load
    !> The two drawn points of link l farthest apart (its joints; its centre of mass only when
    !> it has fewer than two), and their positions.
    pure subroutine couple_points(l, n1, n2, p1, p2)
      integer, intent(in) :: l
      character(len=16), intent(out) :: n1, n2
      real(wp), intent(out) :: p1(2), p2(2)
      character(len=16), allocatable :: names(:)
      integer :: a, b, q
      real(wp) :: best
      allocate (names(0))
      do q = 1, size(drawing%points)
        associate (pn => drawing%points(q)%name)
          if (.not. lists(topo, l, trim(pn)) .or. sliding_on(topo, l, trim(pn))) cycle
          if (trim(pn) == "S"//trim(topo%links(l)%name)) cycle
          names = [character(len=16) :: names, drawing%points(q)%name]
        end associate
      end do
      if (size(names) < 2 .and. drawing%point_index("S"//trim(topo%links(l)%name)) > 0) names = [character(len=16) :: &
        names, "S"//trim(topo%links(l)%name)]
      n1 = ""
      n2 = ""
      p1 = 0.0_wp
      p2 = 0.0_wp
      if (size(names) == 0) return
      n1 = names(1)
      n2 = names(1)
      best = -1.0_wp
      do a = 1, size(names)
        do b = a + 1, size(names)
          if (norm2(drawing%at(trim(names(a))) - drawing%at(trim(names(b)))) > best) then
            best = norm2(drawing%at(trim(names(a))) - drawing%at(trim(names(b))))
            n1 = names(a)
            n2 = names(b)
          end if
        end do
      end do
      p1 = drawing%at(trim(n1))
      p2 = drawing%at(trim(n2))
    end subroutine couple_points
    !> The name of the drawn point of link l at p ("B"; the point of l under another link's
    !> point, as the plans name it, "B3"; "" for none).
    pure function point_at(l, p) result(name)
      integer, intent(in) :: l
      real(wp), intent(in) :: p(2)
      character(len=16) :: name
      character(len=16) :: other
      integer :: q
      real(wp) :: tol
      name = ""
      other = ""
      tol = 1.0e-9_wp * (1.0_wp + norm2(p))
      do q = 1, size(drawing%points)
        associate (pt => drawing%points(q))
          if (norm2(pt%p - p) > tol) cycle
          if (l > 0) then
            if (lists(topo, l, trim(pt%name)) .and. .not. sliding_on(topo, l, trim(pt%name))) then
              name = pt%name
              return
            end if
            if (any(plans%velocities%name == coincident(trim(pt%name), trim(topo%links(l)%name)))) then
              name = coincident(trim(pt%name), trim(topo%links(l)%name))
            else if (len_trim(other) == 0) then
              other = coincident(trim(pt%name), trim(topo%links(l)%name))
            end if
          else if (len_trim(other) == 0) then
            other = pt%name
          end if
        end associate
      end do
      if (len_trim(name) == 0) name = other
    end function point_at
    !> The image's name on the plan: the point's name in lower case ("s2", "b3"), or the
    !> load's when its point has no name.
    pure function image_name(l, p, load) result(name)
      integer, intent(in) :: l
      real(wp), intent(in) :: p(2)
      character(*), intent(in) :: load
      character(len=:), allocatable :: name
      name = lower(trim(point_at(l, p)))
      if (len(name) == 0) name = lower(load)
    end function image_name
    !> The balancing force at the pin B of the driving link d (the joint farthest from its
    !> pivot A), perpendicular to AB: P_bal = M / l_AB; a couple when d has no pivot.
    pure subroutine balancing_at_pin(d, item, length)
      integer, intent(in) :: d
      type(lever_load_t), intent(out) :: item
      !> The pin's distance from the pivot, m (0: a couple).
      real(wp), intent(out) :: length
      character(len=:), allocatable :: pivot
      character(len=16) :: pin
      real(wp) :: a(2), b(2), best
      integer :: q
      pivot = pivot_of(topo, d)
      pin = ""
      best = 0.0_wp
      length = 0.0_wp
      if (len(pivot) > 0) then
        a = drawing%at(pivot)
        do q = 1, size(topo%links(d)%points)
          associate (pn => topo%links(d)%points(q))
            if (drawing%point_index(trim(pn)) == 0 .or. sliding_on(topo, d, trim(pn))) cycle
            if (norm2(drawing%at(trim(pn)) - a) > best) then
              best = norm2(drawing%at(trim(pn)) - a)
              pin = pn
            end if
          end associate
        end do
      end if
      if (len_trim(pin) == 0 .or. best <= 0.0_wp) then
        item = moment_load(plans%driver, plans%effort, d, 0)
        return
      end if
      b = drawing%at(trim(pin))
      item = force_load("P_bal", plans%effort / best**2 * perp(b - a), b, d, 0)
      length = best
    end subroutine balancing_at_pin
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
    pure subroutine pair_friction_of(plans)
      !> The lever's plans (passed: a pure procedure defines no variable of its host).
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
    end subroutine pair_friction_of
    !> Angular velocity of link l (0: the frame), rad/s.
    pure real(wp) function rate_of(l)
      integer, intent(in) :: l
      rate_of = 0.0_wp
      if (l > 0) rate_of = omega(l)
    end function rate_of
  end subroutine lever_of

end module kinetostat_plans_lever
