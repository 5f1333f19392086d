!> Load tables of a deck: a load's value over a position (a link's angle, a slider's stroke,
!> a drive's coordinate) given as (position, value) points, read and checked the same way by
!> every deck group that has them (`&assur`, `&linkage`), and interpolated linearly.
module kinetostat_load_table
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, real_str
  use kinetostat_deck, only: deck_context_t, deck_error, require_rule, count_values
  implicit none
  private
  public :: max_table_points, read_table_points, table_interpolate, table_cyclic

  !> Capacity of a load table, (position, value) points (0.25 deg over 720 deg).
  integer, parameter :: max_table_points = 2881

contains

  !> The points of table `name` as read (pairs position, value; unset after them): at least
  !> one pair, positions strictly increasing (else exit 2 naming the variable and the point).
  subroutine read_table_points(ctx, name, table, x, v, error)
    type(deck_context_t), intent(in) :: ctx
    !> The variable, e.g. "force(1)%table".
    character(*), intent(in) :: name
    !> The table as read.
    real(wp), intent(in) :: table(:)
    !> Positions (deg or m) and values (N or N*m) of the points.
    real(wp), allocatable, intent(out) :: x(:), v(:)
    type(error_t), allocatable, intent(out) :: error
    integer :: n_values, k
    call count_values(ctx, name, table, n_values, error); if (allocated(error)) return
    call require_rule(ctx, name, modulo(n_values, 2) == 0, "needs pairs (position, value), got "// &
      int_str(n_values)//" numbers", error)
    if (allocated(error)) return
    x = table(1:n_values:2)
    v = table(2:n_values:2)
    do k = 2, size(x)
      if (.not. x(k) > x(k - 1)) then
        call deck_error(ctx, name, "positions must be strictly increasing: point "//int_str(k)// &
          " ("//real_str(x(k))//") after "//real_str(x(k - 1)), error)
        return
      end if
    end do
  end subroutine read_table_points

  !> A table's value at position q (deg or m; inside the table): linear interpolation on the
  !> segment holding q (the first segment at or below x(1)).
  pure real(wp) function table_interpolate(x, v, q) result(value)
    !> Positions and values of the points.
    real(wp), intent(in) :: x(:), v(:)
    !> Position, deg or m.
    real(wp), intent(in) :: q
    !> Segment of the table holding q, and the bounds of its search.
    integer :: seg, lo, hi
    if (size(x) == 1) then
      value = v(1)
      return
    end if
    ! the last segment whose start is below q (binary search)
    lo = 1
    hi = size(x) - 1
    do while (hi > lo)
      seg = (lo + hi + 1) / 2
      if (q > x(seg)) then
        lo = seg
      else
        hi = seg - 1
      end if
    end do
    seg = lo
    value = v(seg) + (v(seg + 1) - v(seg)) * (q - x(seg)) / (x(seg + 1) - x(seg))
  end function table_interpolate

  !> An angle as a table's abscissa, deg: `q_deg` taken modulo `period` (360, or 720 over a
  !> four-stroke cycle) into [x1, x1 + period).
  elemental real(wp) function table_cyclic(x1, q_deg, period) result(q)
    !> The table's first position, deg.
    real(wp), intent(in) :: x1
    !> The angle, deg.
    real(wp), intent(in) :: q_deg
    !> The period, deg.
    real(wp), intent(in) :: period
    q = x1 + modulo(q_deg - x1, period)
  end function table_cyclic

end module kinetostat_load_table
