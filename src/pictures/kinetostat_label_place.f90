!> Placement of text labels on a sheet so that no two overlap. A label's box is what a test
!> can measure from the SVG alone: width = 0.6 x font size x characters (UTF-8 characters),
!> height = font size, from 0.8 x font size above the baseline to 0.2 x font size below it,
!> placed horizontally by its text-anchor. Every text written on a sheet is either reserved
!> (a fixed text: a title, a legend) or placed (a label that belongs to a point or an arrow:
!> the first free spot near it, preferring spots away from the drawing's lines; beside its
!> arrow first, then around its point, then farther out with a leader line). `place_box`
!> places any box (a typeset text's) among obstacle segments that have widths (the strokes of
!> a sheet on the drawing model); placed strictly it takes no spot over a line while one is
!> free, and its leader lines cross no label.
module kinetostat_label_place
  use kinetostat_kinds, only: wp, pi
  use kinetostat_format, only: fixed_number
  implicit none
  private
  public :: outward_none, outward_leaders, outward_all
  public :: label_boxes_t, text_chars, title_attributes, anchor_start, anchor_middle, anchor_end, segment_box_distance

  !> Where a label placed strictly goes (place_box): near its point; with a leader line
  !> as far out as may be when it needs one; every label so.
  integer, parameter :: outward_none = 0, outward_leaders = 1, outward_all = 2
  !> text-anchor start (the box begins at x).
  integer, parameter :: anchor_start = 1
  !> text-anchor middle (the box is centred on x).
  integer, parameter :: anchor_middle = 2
  !> text-anchor end (the box ends at x).
  integer, parameter :: anchor_end = 3
  !> Free space kept between two boxes, mm.
  real(wp), parameter :: box_gap = 0.2_wp
  !> Rings of candidate spots around a point; beyond the second a leader line is drawn.
  integer, parameter :: ring_count = 14
  !> Directions per ring.
  integer, parameter :: ring_directions = 16
  !> Least distance a label placed strictly keeps from a line's edge, mm.
  real(wp), parameter :: line_gap = 0.15_wp
  !> A label placed strictly farther than this from its point (its arrow) gets a leader, mm.
  real(wp), parameter :: leader_distance = 4.0_wp
  !> Clearance from the lines beyond which a spot scores no better, mm (the search looks no
  !> farther for lines: a clearance is the least of this and the true one).
  real(wp), parameter :: room_enough = 1.5_wp
  !> Slack of the bounding-box tests that skip a segment before its exact distance is taken,
  !> mm (rounding of the exact distance is far below it, so a skip never changes a result).
  real(wp), parameter :: skip_slack = 1.0e-9_wp
  !> Side of a cell of the grid that files the segments near a label's point, mm.
  real(wp), parameter :: cell_side = 4.0_wp

  !> The boxes taken on a sheet.
  type :: label_boxes_t
    !> Boxes (x0, y0, x1, y1), mm, one per column.
    real(wp), allocatable :: box(:, :)
  contains
    procedure :: reserve
    procedure :: reserve_box
    procedure :: is_free
    procedure :: place_box
    procedure :: line_is_free
  end type label_boxes_t

contains

  !> Number of characters of UTF-8 `text` (continuation bytes not counted).
  pure integer function text_chars(text)
    !> Text, UTF-8.
    character(*), intent(in) :: text
    integer :: i
    text_chars = 0
    do i = 1, len(text)
      if (iand(ichar(text(i:i)), 192) /= 128) text_chars = text_chars + 1
    end do
  end function text_chars

  !> Attributes of a title line of class `class_name` (font size `font_size`, mm) that must fit
  !> `width` mm: the class alone, or with a smaller font size (bold capitals taken as 0.72 x
  !> font size wide) when the text is longer.
  pure function title_attributes(text, class_name, font_size, width) result(styling)
    !> The text, UTF-8.
    character(*), intent(in) :: text, class_name
    !> Font size of the class, mm; width available, mm.
    real(wp), intent(in) :: font_size, width
    character(len=:), allocatable :: styling
    real(wp) :: fitted
    styling = 'class="'//class_name//'"'
    fitted = width / (0.72_wp * max(1, text_chars(text)))
    if (fitted >= font_size) return
    styling = styling//' style="font-size: '//fixed_number(floor(fitted * 100.0_wp) / 100.0_wp, 2)//'px"'
  end function title_attributes

  !> Take the box of a text written at (x, y) (baseline) with `font_size` (mm) and `anchor`.
  pure subroutine reserve(self, x, y, text, font_size, anchor)
    class(label_boxes_t), intent(inout) :: self
    !> Anchor point of the text, mm (y: baseline).
    real(wp), intent(in) :: x, y
    !> The text, UTF-8.
    character(*), intent(in) :: text
    !> Font size, mm.
    real(wp), intent(in) :: font_size
    !> anchor_start, anchor_middle or anchor_end.
    integer, intent(in) :: anchor
    real(wp) :: w, x0
    w = 0.6_wp * font_size * text_chars(text)
    select case (anchor)
    case (anchor_middle)
      x0 = x - 0.5_wp * w
    case (anchor_end)
      x0 = x - w
    case default
      x0 = x
    end select
    call self%reserve_box([x0, y - 0.8_wp * font_size, x0 + w, y + 0.2_wp * font_size])
  end subroutine reserve

  !> Take a box (x0, y0, x1, y1), mm.
  pure subroutine reserve_box(self, b)
    class(label_boxes_t), intent(inout) :: self
    !> The box, mm.
    real(wp), intent(in) :: b(4)
    real(wp), allocatable :: grown(:, :)
    integer :: n
    if (.not. allocated(self%box)) allocate (self%box(4, 0))
    n = size(self%box, 2)
    allocate (grown(4, n + 1))
    grown(:, 1:n) = self%box
    grown(:, n + 1) = b
    call move_alloc(grown, self%box)
  end subroutine reserve_box

  !> Whether box `b` (x0, y0, x1, y1) keeps `box_gap` from every box taken.
  pure logical function is_free(self, b)
    class(label_boxes_t), intent(in) :: self
    !> The box, mm.
    real(wp), intent(in) :: b(4)
    integer :: i
    is_free = .true.
    if (.not. allocated(self%box)) return
    do i = 1, size(self%box, 2)
      if (b(1) < self%box(3, i) + box_gap .and. self%box(1, i) < b(3) + box_gap .and. &
        b(2) < self%box(4, i) + box_gap .and. self%box(2, i) < b(4) + box_gap) then
        is_free = .false.
        return
      end if
    end do
  end function is_free

  !> Place a box `width` mm wide reaching `above` mm above its baseline and `below` mm below
  !> it (a label, text-anchor middle, centred on tx) for the point (px, py), mm, inside
  !> `bounds` (x0, y0, x1, y1): on a box no label has taken, as far as may be from the
  !> obstacle segments. With `tail` (the tail of an arrow whose tip is the point) the spots
  !> beside the arrow come first. Rings of spots around the point follow, direction `base`
  !> (rad, on the sheet: y down) first. (tx, ty) is the centre of the box's baseline;
  !> `leader` is true when the label sits away from its point (the caller draws a line to
  !> it). The obstacle segment k (ox, oy: from point 2k-1 to point 2k; equal ends make a
  !> point) is a band `half_widths(k)`
  !> mm each side of its line (a stroke's half width). With `strict` no spot whose box comes
  !> nearer than `line_gap` to an obstacle is taken while one exists (rings around the point,
  !> then farther out with a leader line that crosses no label); failing that, a spot whose
  !> leader line crosses no label, nearest the lines' least; failing that, any spot. The box
  !> is taken. `relaxed` tells whether it fell back so (a strict placement that found no spot
  !> off the lines with a free leader line).
  pure subroutine place_box(self, width, above, below, px, py, base, ox, oy, half_widths, bounds, strict, tx, ty, &
      leader, tail, relaxed, outward)
    class(label_boxes_t), intent(inout) :: self
    !> Width of the box, mm.
    real(wp), intent(in) :: width
    !> Reach of the box above and below its baseline, mm.
    real(wp), intent(in) :: above, below
    !> The point labelled, mm.
    real(wp), intent(in) :: px, py
    !> Preferred direction from the point, rad (sheet coordinates).
    real(wp), intent(in) :: base
    !> Obstacle segments, mm (ends in pairs).
    real(wp), intent(in) :: ox(:), oy(:)
    !> Half width of each obstacle segment, mm.
    real(wp), intent(in) :: half_widths(:)
    !> Where labels may go: x0, y0, x1, y1, mm.
    real(wp), intent(in) :: bounds(4)
    !> Whether lines are forbidden ground (see above).
    logical, intent(in) :: strict
    !> Baseline centre of the text, mm.
    real(wp), intent(out) :: tx, ty
    !> Whether a leader line is needed.
    logical, intent(out) :: leader
    !> Tail of the arrow ending at the point, mm.
    real(wp), intent(in), optional :: tail(2)
    !> Whether a strict placement fell back to a spot near a line or with a crossing leader.
    logical, intent(out), optional :: relaxed
    !> Where the label goes, placed strictly: near its point (outward_none, the default);
    !> a label with a leader line as far out as the rings reach, leaving the space near a
    !> crowded point to the labels that come after (outward_leaders); every label so, with a
    !> leader line (outward_all).
    integer, intent(in), optional :: outward
    real(wp) :: hw, hh, best, cx, cy, d, u(2), nrm(2), length, bx, by, zone(4)
    integer :: i, ring, side, pass, nx, ny
    !> The grid over `zone`: the segments filed in cell c (numbered from 1 along x, then y)
    !> are filed(first(c):first(c + 1) - 1); a segment's lowest cell (cell_x, cell_y, from 0).
    integer, allocatable :: first(:), filed(:), cell_x(:), cell_y(:), every(:)
    logical :: found, hard, free_leader
    real(wp) :: penalty
    integer :: far_out
    far_out = outward_none
    if (present(outward)) far_out = outward
    hw = 0.5_wp * width
    hh = 0.5_wp * (above + below)
    ! the segments that may come within room_enough of a spot's box inside `zone` (which holds
    ! every spot beside the arrow and on the rings) filed in a grid over it: a spot there
    ! looks at the cells its box meets only
    zone = [px - 2.0_wp * hw - 2.4_wp - (ring_count - 1) * 2.5_wp, py - 2.0_wp * hh - 2.2_wp - (ring_count - 1) * 2.5_wp, &
      px + 2.0_wp * hw + 2.4_wp + (ring_count - 1) * 2.5_wp, py + 2.0_wp * hh + 2.2_wp + (ring_count - 1) * 2.5_wp]
    if (present(tail)) zone = [min(zone(1), tail(1) - 2.0_wp * hw - 1.6_wp), min(zone(2), tail(2) - 2.0_wp * hh - 1.6_wp), &
      max(zone(3), tail(1) + 2.0_wp * hw + 1.6_wp), max(zone(4), tail(2) + 2.0_wp * hh + 1.6_wp)]
    nx = max(1, ceiling((zone(3) - zone(1)) / cell_side))
    ny = max(1, ceiling((zone(4) - zone(2)) / cell_side))
    call file_segments(first, filed, cell_x, cell_y)
    every = [(i, i = 1, size(ox) / 2)]
    length = 0.0_wp
    best = -huge(1.0_wp)
    found = .false.
    bx = px
    by = py
    ! strict: first only spots off every line; if there is none, the best of any spot
    do pass = 1, merge(3, 1, strict)
      hard = strict .and. pass == 1
      free_leader = strict .and. pass <= 2
      ! beside the arrow: beyond its tip, then along its shaft on either side
      if (present(tail)) then
        length = hypot(px - tail(1), py - tail(2))
        if (length > 0.0_wp) then
          u = [px - tail(1), py - tail(2)] / length
          nrm = [-u(2), u(1)]
          call try(best, bx, by, found, px + u(1) * (hw + 0.6_wp), py + u(2) * (hh + 0.6_wp), 0.0_wp)
          do i = 1, 4
            do side = -1, 1, 2
              d = 1.0_wp - 0.2_wp * i
              call try(best, bx, by, found, px - u(1) * d * length + side * nrm(1) * (hw + 0.6_wp), &
                py - u(2) * d * length + side * nrm(2) * (hh + 0.6_wp), 0.3_wp * i)
            end do
          end do
        end if
      end if
      ! rings around the point
      do ring = 1, ring_count
        if (found .and. ring > 4 .and. far_out == outward_none) exit
        do i = 0, ring_directions - 1
          d = base + i * 2.0_wp * pi / ring_directions
          cx = px + cos(d) * (hw + 1.4_wp + (ring - 1) * 2.5_wp)
          cy = py + sin(d) * (hh + 1.2_wp + (ring - 1) * 2.5_wp)
          penalty = 0.6_wp * (ring - 1)
          ! outward: a spot with a leader line (outward_all: any spot) as far out as the rings go
          if (far_out == outward_all .or. far_out == outward_leaders .and. needs_leader(cx, cy)) then
            penalty = 3.0_wp - 0.1_wp * ring
          end if
          call try(best, bx, by, found, cx, cy, penalty + 0.02_wp * min(i, ring_directions - i))
        end do
      end do
      ! last resort: the first free spot of a grid over the bounds, nearest first
      if (.not. found) then
        do ring = 1, 200
          do i = 0, 4 * ring - 1
            d = i * 2.0_wp * pi / (4 * ring)
            call try(best, bx, by, found, px + ring * 1.5_wp * cos(d), py + ring * 1.0_wp * sin(d), 100.0_wp + ring)
          end do
          if (found) exit
        end do
      end if
      if (found) exit
    end do
    if (present(relaxed)) relaxed = strict .and. pass > 1
    leader = needs_leader(bx, by)
    tx = bx
    ty = by + hh - below
    call self%reserve_box([bx - hw, by - hh, bx + hw, by + hh])
  contains
    !> Whether a label centred at (qx, qy) is away from its point (a leader line joins them):
    !> placed strictly, when its box is more than `leader_distance` from the point (from the
    !> arrow, for an arrow's label); else when its centre is beyond the first rings.
    pure logical function needs_leader(qx, qy)
      real(wp), intent(in) :: qx, qy
      real(wp) :: b(4)
      if (strict) then
        b = [qx - hw, qy - hh, qx + hw, qy + hh]
        if (present(tail)) then
          if (length > 0.0_wp) then
            needs_leader = segment_box_distance(tail, [px, py], b) > leader_distance
            return
          end if
        end if
        needs_leader = point_box_distance([px, py], b) > leader_distance
        return
      end if
      needs_leader = hypot((qx - px) / (hw + 1.4_wp), (qy - py) / (hh + 1.2_wp)) > 1.6_wp
      if (present(tail)) then
        if (length > 0.0_wp) needs_leader = needs_leader .and. distance_to_segment(qx, qy, tail, [px, py]) > hw + hh + 1.5_wp
      end if
    end function needs_leader
    !> A candidate centre (qx, qy) at `penalty` mm: kept (best, bx, by, found) when its box
    !> is inside `bounds`, free, off the lines (hard), and scores better than the best so far.
    pure subroutine try(best, bx, by, found, qx, qy, penalty)
      real(wp), intent(inout) :: best, bx, by
      logical, intent(inout) :: found
      real(wp), intent(in) :: qx, qy, penalty
      real(wp) :: b(4), score, room, e(2)
      b = [qx - hw, qy - hh, qx + hw, qy + hh]
      if (b(1) < bounds(1) .or. b(3) > bounds(3) .or. b(2) < bounds(2) .or. b(4) > bounds(4)) return
      if (.not. self%is_free(b)) return
      if (b(1) >= zone(1) .and. b(3) <= zone(3) .and. b(2) >= zone(2) .and. b(4) <= zone(4)) then
        room = clearance_filed(b)
      else
        room = clearance(b, every)
      end if
      if (hard .and. room < line_gap) return
      if (free_leader) then
        if (needs_leader(qx, qy)) then
          ! the leader line from the point to the box's nearest point crosses no label
          e = [max(b(1), min(b(3), px)), max(b(2), min(b(4), py))]
          if (.not. self%line_is_free([px, py], e)) return
        end if
      end if
      score = min(room, room_enough) - penalty
      if (score > best + 1.0e-9_wp) then
        best = score
        bx = qx
        by = qy
        found = .true.
      end if
    end subroutine try
    !> Least distance from the box `b` (x0, y0, x1, y1) to the bands of the obstacle segments
    !> numbered in `segments` (half width `half_widths(k)` each side of segment k), mm (0 or
    !> less: the box touches one), or room_enough when that is less. A segment whose bounding
    !> box is farther than the least so far is not measured: it cannot be nearer.
    pure real(wp) function clearance(b, segments)
      real(wp), intent(in) :: b(4)
      integer, intent(in) :: segments(:)
      integer :: i, k
      clearance = room_enough
      do i = 1, size(segments)
        k = 2 * segments(i) - 1
        if (.not. reachable(b, k, clearance)) cycle
        clearance = min(clearance, segment_box_distance([ox(k), oy(k)], [ox(k + 1), oy(k + 1)], b) - &
          half_widths((k + 1) / 2))
      end do
    end function clearance
    !> clearance(b, all segments) for a box inside `zone`, from the segments filed in the
    !> cells it meets (each measured once: in the lowest cell its own cells share with them).
    pure real(wp) function clearance_filed(b)
      real(wp), intent(in) :: b(4)
      integer :: ix, iy, ix0, iy0, ix1, iy1, j, s, k
      call cell_range(b, 0.0_wp, ix0, iy0, ix1, iy1)
      clearance_filed = room_enough
      do iy = iy0, iy1
        do ix = ix0, ix1
          do j = first(ix + nx * iy + 1), first(ix + nx * iy + 2) - 1
            s = filed(j)
            if (ix /= max(ix0, cell_x(s)) .or. iy /= max(iy0, cell_y(s))) cycle
            k = 2 * s - 1
            if (.not. reachable(b, k, clearance_filed)) cycle
            clearance_filed = min(clearance_filed, segment_box_distance([ox(k), oy(k)], [ox(k + 1), oy(k + 1)], b) - &
              half_widths(s))
          end do
        end do
      end do
    end function clearance_filed
    !> File every segment that may come within room_enough of a box inside `zone` in the
    !> cells of the grid that its band, grown by room_enough, meets.
    pure subroutine file_segments(first, filed, cell_x, cell_y)
      integer, allocatable, intent(out) :: first(:), filed(:), cell_x(:), cell_y(:)
      integer :: s, k, ix, iy, ix0, iy0, ix1, iy1, pass_no, c
      integer, allocatable :: fill(:)
      allocate (first(nx * ny + 1), fill(nx * ny), cell_x(size(ox) / 2), cell_y(size(ox) / 2))
      fill = 0
      do pass_no = 1, 2
        do s = 1, size(ox) / 2
          k = 2 * s - 1
          if (.not. reachable(zone, k, room_enough)) cycle
          ! the band's bounding box grown by room_enough (and a margin above the rounding)
          call cell_range([min(ox(k), ox(k + 1)), min(oy(k), oy(k + 1)), max(ox(k), ox(k + 1)), max(oy(k), oy(k + 1))], &
            half_widths(s) + room_enough + 1.0e-6_wp, ix0, iy0, ix1, iy1)
          cell_x(s) = ix0
          cell_y(s) = iy0
          do iy = iy0, iy1
            do ix = ix0, ix1
              c = ix + nx * iy + 1
              fill(c) = fill(c) + 1
              if (pass_no == 2) filed(first(c) + fill(c) - 1) = s
            end do
          end do
        end do
        if (pass_no == 2) exit
        first(1) = 1
        do c = 1, nx * ny
          first(c + 1) = first(c) + fill(c)
        end do
        allocate (filed(first(nx * ny + 1) - 1))
        fill = 0
      end do
    end subroutine file_segments
    !> The cells (from 0, within the grid) that the box `b` grown by `grow` mm meets.
    pure subroutine cell_range(b, grow, ix0, iy0, ix1, iy1)
      real(wp), intent(in) :: b(4), grow
      integer, intent(out) :: ix0, iy0, ix1, iy1
      ix0 = cell_of(b(1) - grow, zone(1), nx)
      ix1 = cell_of(b(3) + grow, zone(1), nx)
      iy0 = cell_of(b(2) - grow, zone(2), ny)
      iy1 = cell_of(b(4) + grow, zone(2), ny)
    end subroutine cell_range
    !> The cell (0 to n - 1) of the coordinate v on an axis of the grid starting at v0.
    pure integer function cell_of(v, v0, n)
      real(wp), intent(in) :: v, v0
      integer, intent(in) :: n
      cell_of = floor(min(max((v - v0) / cell_side, 0.0_wp), real(n - 1, wp)))
    end function cell_of
    !> Whether the band of the segment from point k to point k + 1 may come nearer than
    !> `reach` to the box `b` (by their bounding boxes, with skip_slack to spare).
    pure logical function reachable(b, k, reach)
      real(wp), intent(in) :: b(4), reach
      integer, intent(in) :: k
      real(wp) :: gap_x, gap_y
      gap_x = max(min(ox(k), ox(k + 1)) - b(3), b(1) - max(ox(k), ox(k + 1)), 0.0_wp)
      gap_y = max(min(oy(k), oy(k + 1)) - b(4), b(2) - max(oy(k), oy(k + 1)), 0.0_wp)
      reachable = max(gap_x, gap_y) - half_widths((k + 1) / 2) <= reach + skip_slack
    end function reachable
  end subroutine place_box

  !> Whether the segment a-b (a leader line) keeps 0.1 mm from every box taken.
  pure logical function line_is_free(self, a, b)
    class(label_boxes_t), intent(in) :: self
    !> Ends of the segment, mm.
    real(wp), intent(in) :: a(2), b(2)
    integer :: i
    line_is_free = .true.
    if (.not. allocated(self%box)) return
    do i = 1, size(self%box, 2)
      if (segment_box_distance(a, b, self%box(:, i)) <= 0.1_wp) then
        line_is_free = .false.
        return
      end if
    end do
  end function line_is_free


  !> Distance from the segment a-b to the box `box` (x0, y0, x1, y1), mm: 0 when the segment
  !> meets the box (crosses it or lies inside it).
  pure real(wp) function segment_box_distance(a, b, box) result(distance)
    real(wp), intent(in) :: a(2), b(2), box(4)
    real(wp) :: t0, t1, d(2), p(4), q(4)
    integer :: i
    ! Liang-Barsky: the part of the segment inside the box
    d = b - a
    p = [-d(1), d(1), -d(2), d(2)]
    q = [a(1) - box(1), box(3) - a(1), a(2) - box(2), box(4) - a(2)]
    t0 = 0.0_wp
    t1 = 1.0_wp
    do i = 1, 4
      if (p(i) == 0.0_wp) then
        if (q(i) < 0.0_wp) then
          t0 = 2.0_wp
          exit
        end if
      else if (p(i) < 0.0_wp) then
        t0 = max(t0, q(i) / p(i))
      else
        t1 = min(t1, q(i) / p(i))
      end if
    end do
    if (t0 <= t1) then
      distance = 0.0_wp
      return
    end if
    ! apart: the nearest of the segment's ends to the box and of the box's corners to the segment
    distance = min(point_box_distance(a, box), point_box_distance(b, box), &
      distance_to_segment(box(1), box(2), a, b), distance_to_segment(box(3), box(2), a, b), &
      distance_to_segment(box(1), box(4), a, b), distance_to_segment(box(3), box(4), a, b))
  end function segment_box_distance

  !> Distance from point p to the box (x0, y0, x1, y1), mm (0 inside).
  pure real(wp) function point_box_distance(p, box)
    real(wp), intent(in) :: p(2), box(4)
    point_box_distance = hypot(max(box(1) - p(1), 0.0_wp, p(1) - box(3)), max(box(2) - p(2), 0.0_wp, p(2) - box(4)))
  end function point_box_distance

  !> Distance from (x, y) to the segment a-b, mm.
  pure real(wp) function distance_to_segment(x, y, a, b)
    real(wp), intent(in) :: x, y, a(2), b(2)
    real(wp) :: d(2), t
    d = b - a
    t = 0.0_wp
    if (dot_product(d, d) > 0.0_wp) t = max(0.0_wp, min(1.0_wp, ((x - a(1)) * d(1) + (y - a(2)) * d(2)) / dot_product(d, d)))
    distance_to_segment = hypot(x - a(1) - t * d(1), y - a(2) - t * d(2))
  end function distance_to_segment

end module kinetostat_label_place
