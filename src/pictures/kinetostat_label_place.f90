!> Placement of text labels on a sheet so that no two overlap. A label's box is what a test
!> can measure from the SVG alone: width = 0.6 x font size x characters (UTF-8 characters),
!> height = font size, from 0.8 x font size above the baseline to 0.2 x font size below it,
!> placed horizontally by its text-anchor. Every text written on a sheet is either reserved
!> (a fixed text: a title, a legend) or placed (a label that belongs to a point or an arrow:
!> the first free spot near it, preferring spots away from the drawing's lines; beside its
!> arrow first, then around its point, then farther out with a leader line).
module kinetostat_label_place
  use kinetostat_kinds, only: wp, pi
  use kinetostat_format, only: fixed_number
  implicit none
  private
  public :: label_boxes_t, text_chars, title_attributes, anchor_start, anchor_middle, anchor_end

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

  !> The boxes taken on a sheet.
  type :: label_boxes_t
    !> Boxes (x0, y0, x1, y1), mm, one per column.
    real(wp), allocatable :: box(:, :)
  contains
    procedure :: reserve
    procedure :: reserve_box
    procedure :: is_free
    procedure :: place
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

  !> Place a label (text-anchor middle) for the point (px, py), mm, inside `bounds` (x0, y0,
  !> x1, y1): on a box no label has taken, as far as may be from the obstacle segments
  !> (ox, oy: segment k from point 2k-1 to point 2k; equal ends make a point). With
  !> `tail` (the tail of an arrow whose tip is the point) the spots beside the arrow come
  !> first. Rings of spots around the point follow, direction `base` (rad, on the sheet:
  !> y down) first. (tx, ty) is the centre of the text's baseline; `leader` is true when the
  !> label sits away from its point (the caller draws a line to it). The box is taken.
  pure subroutine place(self, text, font_size, px, py, base, ox, oy, bounds, tx, ty, leader, tail)
    class(label_boxes_t), intent(inout) :: self
    !> The text, UTF-8.
    character(*), intent(in) :: text
    !> Font size, mm.
    real(wp), intent(in) :: font_size
    !> The point labelled, mm.
    real(wp), intent(in) :: px, py
    !> Preferred direction from the point, rad (sheet coordinates).
    real(wp), intent(in) :: base
    !> Obstacle segments, mm (ends in pairs).
    real(wp), intent(in) :: ox(:), oy(:)
    !> Where labels may go: x0, y0, x1, y1, mm.
    real(wp), intent(in) :: bounds(4)
    !> Baseline centre of the text, mm.
    real(wp), intent(out) :: tx, ty
    !> Whether a leader line is needed.
    logical, intent(out) :: leader
    !> Tail of the arrow ending at the point, mm.
    real(wp), intent(in), optional :: tail(2)
    real(wp) :: hw, hh, best, cx, cy, d, u(2), nrm(2), length, bx, by
    integer :: i, ring, side
    logical :: found
    hw = 0.3_wp * font_size * text_chars(text)
    hh = 0.5_wp * font_size
    best = -huge(1.0_wp)
    found = .false.
    bx = px
    by = py
    ! beside the arrow: beyond its tip, then along its shaft on either side
    if (present(tail)) then
      length = hypot(px - tail(1), py - tail(2))
      if (length > 0.0_wp) then
        u = [px - tail(1), py - tail(2)] / length
        nrm = [-u(2), u(1)]
        call try(self, hw, hh, bounds, ox, oy, best, bx, by, found, px + u(1) * (hw + 0.6_wp), py + u(2) * (hh + 0.6_wp), 0.0_wp)
        do i = 1, 4
          do side = -1, 1, 2
            d = 1.0_wp - 0.2_wp * i
            call try(self, hw, hh, bounds, ox, oy, best, bx, by, found, px - u(1) * d * length + side * nrm(1) * (hw + 0.6_wp), &
              py - u(2) * d * length + side * nrm(2) * (hh + 0.6_wp), 0.3_wp * i)
          end do
        end do
      end if
    end if
    ! rings around the point
    do ring = 1, ring_count
      if (found .and. ring > 4) exit
      do i = 0, ring_directions - 1
        d = base + i * 2.0_wp * pi / ring_directions
        cx = px + cos(d) * (hw + 1.4_wp + (ring - 1) * 2.5_wp)
        cy = py + sin(d) * (hh + 1.2_wp + (ring - 1) * 2.5_wp)
        call try(self, hw, hh, bounds, ox, oy, best, bx, by, found, cx, cy, &
          0.6_wp * (ring - 1) + 0.02_wp * min(i, ring_directions - i))
      end do
    end do
    ! last resort: the first free spot of a grid over the bounds, nearest first
    if (.not. found) then
      do ring = 1, 200
        do i = 0, 4 * ring - 1
          d = i * 2.0_wp * pi / (4 * ring)
          call try(self, hw, hh, bounds, ox, oy, best, bx, by, found, &
            px + ring * 1.5_wp * cos(d), py + ring * 1.0_wp * sin(d), 100.0_wp + ring)
        end do
        if (found) exit
      end do
    end if
    leader = hypot((bx - px) / (hw + 1.4_wp), (by - py) / (hh + 1.2_wp)) > 1.6_wp
    if (present(tail)) then
      if (length > 0.0_wp) leader = leader .and. distance_to_segment(bx, by, tail, [px, py]) > hw + hh + 1.5_wp
    end if
    tx = bx
    ty = by + 0.3_wp * font_size
    call self%reserve_box([bx - hw, by - hh, bx + hw, by + hh])
  end subroutine place

  !> A candidate centre (qx, qy) at `penalty` mm: kept (best, bx, by, found) when its box
  !> (half sizes hw, hh) is inside `bounds`, free, and scores better than the best so far.
  pure subroutine try(self, hw, hh, bounds, ox, oy, best, bx, by, found, qx, qy, penalty)
    type(label_boxes_t), intent(in) :: self
    real(wp), intent(in) :: hw, hh, bounds(4), ox(:), oy(:)
    real(wp), intent(inout) :: best, bx, by
    logical, intent(inout) :: found
    real(wp), intent(in) :: qx, qy, penalty
    real(wp) :: b(4), score
    b = [qx - hw, qy - hh, qx + hw, qy + hh]
    if (b(1) < bounds(1) .or. b(3) > bounds(3) .or. b(2) < bounds(2) .or. b(4) > bounds(4)) return
    if (.not. self%is_free(b)) return
    score = min(clearance(b, ox, oy), 1.5_wp) - penalty
    if (score > best + 1.0e-9_wp) then
      best = score
      bx = qx
      by = qy
      found = .true.
    end if
  end subroutine try

  !> Least distance from the box `b` (sampled on its edges and middle line) to the segments
  !> (ox(2k-1), oy(2k-1))-(ox(2k), oy(2k)), mm.
  pure real(wp) function clearance(b, ox, oy)
    real(wp), intent(in) :: b(4), ox(:), oy(:)
    real(wp) :: sx, sy
    integer :: i, j, k, nx
    clearance = huge(1.0_wp)
    if (size(ox) == 0) return
    nx = 1 + ceiling((b(3) - b(1)) / 1.2_wp)
    do i = 0, nx
      sx = b(1) + (b(3) - b(1)) * i / nx
      do j = 0, 2
        sy = b(2) + 0.5_wp * (b(4) - b(2)) * j
        do k = 1, size(ox) - 1, 2
          clearance = min(clearance, distance_to_segment(sx, sy, [ox(k), oy(k)], [ox(k + 1), oy(k + 1)]))
        end do
      end do
    end do
  end function clearance

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
