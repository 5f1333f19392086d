!> What a run comes to, for parameter studies and the legacy table's footer: per column
!> the largest and smallest value with the input angle where each occurs and the mean over
!> the input angle; the work of the driving moment (or force) over the run; the warning
!> when the step is too coarse to catch a force peak next to a load that switches on or off;
!> and the warning when the steps miss the peak of a load table (table_peak_warning).
module kinetostat_summary
  !$ use omp_lib, only: omp_get_max_threads
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_text, only: int_str, lower, without_blanks
  use kinetostat_step_table, only: step_table_t, col_force, col_force_angle, col_moment, column_tally_t, &
    edge_point_t, echo_record_t, echo_text_kind
  use kinetostat_format, only: cell_number, trimmed_es
  use kinetostat_escape, only: csv_field
  implicit none
  private
  public :: column_stats_t, column_stats, summarized, drive_work, coarse_step_warning, tally_rows, table_peak_warning, &
    table_peak_share
  public :: summary_header, summary_row, summary_values, coarse_step_limit, dynamics_prefix, override_fields, &
    override_has_column

  !> Prefix of the dynamics figures' columns in a summary (dyn_delta, dyn_M_d): their names
  !> are also deck variables (delta, a --vary column) and column summaries (J_red_max).
  character(*), parameter :: dynamics_prefix = "dyn_"

  !> Values closer than this, relative to the column's largest magnitude, are a tie.
  real(wp), parameter :: tie_rel = 1.0e-12_wp
  !> Input steps coarser than this (deg) may miss a force peak next to a load edge.
  real(wp), parameter :: coarse_step_limit = 5.0_wp
  !> A load table's extreme point between two steps is missed when the load there differs
  !> from its values at both steps by more than this share of the table's range.
  real(wp), parameter :: table_peak_share = 0.05_wp
  !> Scale of the values in the sums kept for overflow (a power of two: exact): a value
  !> below 1.8e308 becomes one below 1.4e154, so sums of 10^6 of them stay finite.
  real(wp), parameter :: value_scale = scale(1.0_wp, -512)
  !> Scale of the input (or driver coordinate) steps in those sums: a step below 3.6e308
  !> becomes one below 1e140, so a product with a scaled value stays below 1.4e294.
  real(wp), parameter :: step_scale = scale(1.0_wp, -560)
  !> A trapezoid term below this (2**40) is a subnormal number once scaled by value_scale and
  !> step_scale (2**-1072): such terms stay out of the scaled sums.
  real(wp), parameter :: tiny_term = scale(1.0_wp, 40)

  !> Extremes and mean of one column over a run.
  type :: column_stats_t
    !> Largest value (unit of the column).
    real(wp) :: max = 0.0_wp
    !> Smallest value.
    real(wp) :: min = 0.0_wp
    !> Mean over the input angle (trapezoid rule), or over the rows without one.
    real(wp) :: mean = 0.0_wp
    !> Row of the largest value (the first one on a tie: within `tie_rel` of the column's
    !> largest magnitude, so that roundoff between equal positions, such as 0 and 360 deg,
    !> does not decide).
    integer :: max_row = 0
    !> Row of the smallest value (the first one on a tie).
    integer :: min_row = 0
    !> Input coordinate at max_row (0 without an input column).
    real(wp) :: max_at = 0.0_wp
    !> Input coordinate at min_row.
    real(wp) :: min_at = 0.0_wp
  end type column_stats_t

contains

  !> Whether column `c` takes part in a summary: a CSV column other than the input angle
  !> and other than the angle of a force (a direction modulo 360 deg has no meaningful
  !> extremes or mean); a kinematics column only when `kinematics` (--kinematics).
  pure logical function summarized(table, c, kinematics)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Column index.
    integer, intent(in) :: c
    !> Whether the kinematics columns are shown.
    logical, intent(in) :: kinematics
    summarized = table%columns(c)%csv .and. c /= table%input_column .and. &
      table%columns(c)%kind /= col_force_angle .and. (kinematics .or. .not. table%columns(c)%kinematic)
  end function summarized

  !> Add the rows now in the table (the run's rows row_offset+1 .., in order; the run
  !> pipeline calls this for every block) to the run's tallies: per column the outputs read
  !> (step_table_t's tallied) its extremes and the row and input coordinate of each, its sum
  !> and trapezoid sum; the largest input step; the driver's work; the input coordinate next
  !> to the load edges. The sums run in row order, so they are the same whatever the blocks
  !> and threads. The columns are tallied each on its own (the same sums as row by row), in
  !> parallel with threads.
  subroutine tally_rows(table)
    !> The results (the tallies are updated).
    type(step_table_t), intent(inout) :: table
    !> Rows folded into the columns' tallies at a time (fold_rows).
    integer, parameter :: tile_rows = 64
    !> Fewest rows worth a thread.
    integer, parameter :: min_rows_per_thread = 1024
    integer :: k, c, i, row, d, nc, nt, n, k1, k2, part, parts
    integer, allocatable :: tally(:)
    real(wp) :: x, coordinate, last_d, previous_at, before, term
    real(wp), allocatable :: at(:)
    logical, allocatable :: void(:)
    logical :: work_known, work_in_rad, any_voidable, steady
    nc = size(table%columns)
    n = table%row_count()
    if (table%run_tally%rows == 0) then
      if (allocated(table%run_tally%columns)) deallocate (table%run_tally%columns)
      allocate (table%run_tally%columns(nc))
      if (allocated(table%run_tally%edge_points)) deallocate (table%run_tally%edge_points)
      allocate (table%run_tally%edge_points(0))
      table%run_tally%void_rows = 0
    end if
    if (n == 0) return
    d = 0
    if (allocated(table%driver)) d = table%column_index(table%driver)
    call work_kind(table, d, work_known, work_in_rad)
    allocate (at(n), void(n))
    if (table%input_column > 0) then
      at = table%rows(table%input_column, 1:n)
    else
      at = 0.0_wp
    end if
    if (allocated(table%void_flags)) then
      do k = 1, n
        void(k) = table%is_void(k)
      end do
    else
      void = .false.
    end if
    previous_at = table%run_tally%last_at
    last_d = 0.0_wp
    if (d > 0) last_d = table%run_tally%columns(d)%last
    do k = 1, n
      row = table%row_offset + k
      x = at(k)
      coordinate = 0.0_wp
      if (work_known) then
        if (work_in_rad) then
          coordinate = x * deg_to_rad
        else
          coordinate = table%rows(table%work_column, k)
        end if
      end if
      if (row == 1) then
        table%run_tally%first_at = x
        table%run_tally%largest_step = 0.0_wp
        table%run_tally%work2 = 0.0_wp
        table%run_tally%work2_scaled = 0.0_wp
      else
        table%run_tally%largest_step = max(table%run_tally%largest_step, abs(x - table%run_tally%last_at))
        if (work_known) then
          term = (table%rows(d, k) + last_d) * (coordinate - table%run_tally%last_coordinate)
          table%run_tally%work2 = table%run_tally%work2 + term
          if (.not. abs(term) < tiny_term) table%run_tally%work2_scaled = table%run_tally%work2_scaled + &
            (table%rows(d, k) * value_scale + last_d * value_scale) * &
            (coordinate * step_scale - table%run_tally%last_coordinate * step_scale)
        end if
      end if
      if (void(k)) table%run_tally%void_rows = table%run_tally%void_rows + 1
      ! the driver's last counted value (a void cell leaves it), as its column's tally keeps it
      if (d > 0) then
        if (.not. (void(k) .and. table%columns(d)%voidable)) last_d = table%rows(d, k)
      end if
      if (near_load_edge(row)) table%run_tally%edge_points = [table%run_tally%edge_points, edge_point_t(row, x)]
      table%run_tally%last_at = x
      table%run_tally%last_coordinate = coordinate
      table%run_tally%rows = row
    end do
    ! the columns the run's outputs read (step_table_t's tallied), in `parts` contiguous
    ! shares (one per thread with OpenMP). A row that is void where a tallied column is
    ! voidable, and a row after which a column is not yet counted with its last row (the run's
    ! first row, the row after a void one), go column by column (tally_column); the rows
    ! between, a tile at a time, go two columns at a time (fold_rows: the same figures)
    tally = pack([(c, c = 1, nc)], [(table%tallied(c), c = 1, nc)])
    nt = size(tally)
    any_voidable = .false.
    do i = 1, nt
      any_voidable = any_voidable .or. table%columns(tally(i))%voidable
    end do
    parts = 1
    !$ parts = max(1, min(omp_get_max_threads(), nt, n / min_rows_per_thread))
    !$omp parallel do schedule(static) num_threads(parts) private(c, i, k1, k2, before, steady) if (parts > 1)
    do part = 1, parts
      associate (share => tally((part - 1) * nt / parts + 1:part * nt / parts))
        steady = .true.
        do i = 1, size(share)
          steady = steady .and. table%run_tally%columns(share(i))%count > 0 .and. &
            table%run_tally%columns(share(i))%last_counted
        end do
        k1 = 1
        do while (k1 <= n)
          before = previous_at
          if (k1 > 1) before = at(k1 - 1)
          if (steady .and. .not. (any_voidable .and. void(k1))) then
            k2 = k1
            do while (k2 < n .and. k2 - k1 + 1 < tile_rows)
              if (any_voidable .and. void(k2 + 1)) exit
              k2 = k2 + 1
            end do
            call fold_rows(table%run_tally%columns, share, table%rows, at, k1, k2, table%row_offset, before)
          else
            k2 = k1
            do i = 1, size(share)
              c = share(i)
              call tally_column(table%run_tally%columns(c), table%rows(c, k1:k1), at(k1:k1), void(k1:k1), &
                                table%columns(c)%voidable, table%row_offset + k1 - 1, before)
            end do
            steady = .not. (any_voidable .and. void(k1))
          end if
          k1 = k2 + 1
        end do
      end associate
    end do
    !$omp end parallel do
  contains
    !> Whether a load switches between this row and the one before or after it.
    pure logical function near_load_edge(r)
      integer, intent(in) :: r
      near_load_edge = .false.
      if (.not. allocated(table%load_changes)) return
      if (size(table%load_changes) /= table%total_rows .or. r > size(table%load_changes)) return
      if (r >= 2) near_load_edge = table%load_changes(r)
      if (r < size(table%load_changes)) near_load_edge = near_load_edge .or. table%load_changes(r + 1)
    end function near_load_edge
  end subroutine tally_rows

  !> One column's tally over the rows of a block, in row order (see tally_rows).
  pure subroutine tally_column(t, values, at, void, voidable, row_offset, previous_at)
    !> The column's tally so far (updated).
    type(column_tally_t), intent(inout) :: t
    !> The column's values in the block's rows.
    real(wp), intent(in) :: values(:)
    !> The input coordinate of each row (0 without an input column).
    real(wp), intent(in) :: at(:)
    !> Whether the row is void.
    logical, intent(in) :: void(:)
    !> Whether the column has no value in a void row (such a cell is left out).
    logical, intent(in) :: voidable
    !> Rows of the run before the block.
    integer, intent(in) :: row_offset
    !> Input coordinate of the row before the block.
    real(wp), intent(in) :: previous_at
    real(wp) :: v, x, last_at, tie, term
    integer :: k, row
    ! the tally in a local copy while the rows run (its fields stay in registers instead of
    ! going to memory and back every row)
    type(column_tally_t) :: tl
    tl = t
    last_at = previous_at
    do k = 1, size(values)
      v = values(k)
      x = at(k)
      row = row_offset + k
      ! a cell without a value (void row) is left out of the extremes, sums and means
      if (voidable .and. void(k)) then
        tl%last_counted = .false.
        last_at = x
        cycle
      end if
      tl%largest = max(tl%largest, abs(v))
      if (tl%count == 0) then
        tl = column_tally_t(max=v, min=v, max_row=row, min_row=row, max_at=x, min_at=x, peak=v, peak_row=row, &
                           peak_at=x, largest=abs(v), total=v, area2=0.0_wp, last=v, count=1, span=0.0_wp, &
                           last_counted=.true., total_scaled=v * value_scale, area2_scaled=0.0_wp)
        last_at = x
        cycle
      end if
      tie = tie_rel * tl%largest
      if (v > tl%max + tie) then
        tl%max = v
        tl%max_row = row
        tl%max_at = x
      end if
      if (v < tl%min - tie) then
        tl%min = v
        tl%min_row = row
        tl%min_at = x
      end if
      if (v > tl%peak) then
        tl%peak = v
        tl%peak_row = row
        tl%peak_at = x
      end if
      tl%total = tl%total + v
      tl%count = tl%count + 1
      if (tl%last_counted) then
        term = (v + tl%last) * (x - last_at)
        tl%area2 = tl%area2 + term
        ! (a term whose scaled value would be subnormal is left out of the scaled sum: it is
        ! below 1e-290 of any sum that overflowed, the only one that sum is used for, and
        ! subnormal arithmetic would take most of the run's summary time)
        if (.not. abs(term) < tiny_term) tl%area2_scaled = tl%area2_scaled + (v * value_scale + tl%last * value_scale) * &
                                                          (x * step_scale - last_at * step_scale)
        tl%span = tl%span + (x - last_at)
      end if
      tl%total_scaled = tl%total_scaled + v * value_scale
      tl%last = v
      tl%last_counted = .true.
      last_at = x
    end do
    t = tl
  end subroutine tally_column

  !> Fold rows k1..k2 of the block into the tallies of columns `cols`, every one of them
  !> counted so far with its last row (no void cell among these rows): the figures
  !> tally_column gives row by row, bit for bit. The sums run over the rows in order, two
  !> columns at a time (independent lanes the compiler keeps in one vector register), with
  !> the rows' largest and smallest value, from which fold_extremes finds the extremes; the
  !> overflow guard's scaled trapezoid sum is added row by row (scaled_area) only where a
  !> term reaches it (|term| >= tiny_term, or a sum not finite).
  pure subroutine fold_rows(ts, cols, rows, at, k1, k2, row_offset, before)
    !> The run's tallies of every column (those of `cols` updated).
    type(column_tally_t), intent(inout) :: ts(:)
    !> The columns to fold.
    integer, intent(in) :: cols(:)
    !> The block's values, rows(column, row).
    real(wp), intent(in) :: rows(:, :)
    !> The input coordinate of each row of the block (0 without an input column).
    real(wp), intent(in) :: at(:)
    !> The rows to fold.
    integer, intent(in) :: k1, k2
    !> Rows of the run before the block.
    integer, intent(in) :: row_offset
    !> Input coordinate of row k1 - 1 (of the row before the block when k1 = 1).
    real(wp), intent(in) :: before
    integer, parameter :: lanes = 2
    real(wp), dimension(lanes) :: v, last, hi, lo, total, total_scaled, area2, span, big, term
    real(wp) :: dx(k2 - k1 + 1), last_before
    integer :: lane(lanes), i0, l, k, c, m
    dx(1) = at(k1) - before
    do k = k1 + 1, k2
      dx(k - k1 + 1) = at(k) - at(k - 1)
    end do
    m = size(cols)
    do i0 = 1, m, lanes
      ! (the last lanes repeat the last column where fewer are left; only the real ones are kept)
      do l = 1, lanes
        lane(l) = cols(min(i0 + l - 1, m))
        last(l) = ts(lane(l))%last
        total(l) = ts(lane(l))%total
        total_scaled(l) = ts(lane(l))%total_scaled
        area2(l) = ts(lane(l))%area2
        span(l) = ts(lane(l))%span
      end do
      hi = -huge(1.0_wp)
      lo = huge(1.0_wp)
      big = 0.0_wp
      do k = k1, k2
        do l = 1, lanes
          v(l) = rows(lane(l), k)
        end do
        hi = max(hi, v)
        lo = min(lo, v)
        total = total + v
        total_scaled = total_scaled + v * value_scale
        term = (v + last) * dx(k - k1 + 1)
        area2 = area2 + term
        big = max(big, abs(term))
        span = span + dx(k - k1 + 1)
        last = v
      end do
      do l = 1, min(lanes, m - i0 + 1)
        c = lane(l)
        last_before = ts(c)%last
        ts(c)%total = total(l)
        ts(c)%total_scaled = total_scaled(l)
        ts(c)%area2 = area2(l)
        ts(c)%span = span(l)
        ts(c)%last = last(l)
        ts(c)%count = ts(c)%count + (k2 - k1 + 1)
        ! (a NaN sum: a term overflowed, or a sum before did)
        if (.not. (big(l) < tiny_term .and. area2(l) == area2(l))) then
          call scaled_area(ts(c), rows(c, k1:k2), at(k1:k2), last_before, before)
        end if
        call fold_extremes(ts(c), rows(c, k1:k2), at(k1:k2), row_offset + k1 - 1, hi(l), lo(l))
      end do
    end do
  end subroutine fold_rows

  !> A column's extremes (largest magnitude, largest and smallest value with the tie rule,
  !> peak) over rows in order, as tally_column finds them, given the rows' largest and
  !> smallest value: the tie allowance only grows with the rows, so where those stay within
  !> the bounds of an extreme as it was before the first row, that extreme stays; an
  !> extreme that may change is found row by row (its own loop: the others are not touched).
  pure subroutine fold_extremes(t, values, at, row_offset, hi, lo)
    !> The column's tally (its extremes updated).
    type(column_tally_t), intent(inout) :: t
    !> The column's values in the rows.
    real(wp), intent(in) :: values(:)
    !> The input coordinate of each row.
    real(wp), intent(in) :: at(:)
    !> Rows of the run before the first of them.
    integer, intent(in) :: row_offset
    !> The largest and the smallest of `values`.
    real(wp), intent(in) :: hi, lo
    real(wp) :: tie
    integer :: k
    tie = tie_rel * t%largest
    if (.not. hi <= t%max + tie) call record_by_rows(1.0_wp, t%max, t%max_row, t%max_at)
    if (.not. lo >= t%min - tie) call record_by_rows(-1.0_wp, t%min, t%min_row, t%min_at)
    if (.not. hi <= t%peak) then
      do k = 1, size(values)
        if (values(k) > t%peak) then
          t%peak = values(k)
          t%peak_row = row_offset + k
          t%peak_at = at(k)
        end if
      end do
    end if
    t%largest = max(t%largest, abs(hi), abs(lo))
  contains
    !> The largest value (sense 1) or the smallest (sense -1: the largest of the negated
    !> values, bit for bit the same test, as fl(-a + b) = -fl(a - b)) by the tie rule, row by
    !> row with the column's largest magnitude so far.
    pure subroutine record_by_rows(sense, value, row, value_at)
      !> 1 or -1.
      real(wp), intent(in) :: sense
      !> The extreme so far and the input coordinate at its row (updated).
      real(wp), intent(inout) :: value, value_at
      !> Its row (updated).
      integer, intent(inout) :: row
      real(wp) :: best, largest
      integer :: j
      largest = t%largest
      best = sense * value
      do j = 1, size(values)
        largest = max(largest, abs(values(j)))
        if (sense * values(j) > best + tie_rel * largest) then
          best = sense * values(j)
          row = row_offset + j
          value_at = at(j)
        end if
      end do
      value = sense * best
    end subroutine record_by_rows
  end subroutine fold_extremes

  !> A column's scaled trapezoid sum (the overflow guard's) over rows in order, as
  !> tally_column adds it: the terms not below tiny_term (or not finite).
  pure subroutine scaled_area(t, values, at, last, before)
    !> The column's tally (its area2_scaled updated).
    type(column_tally_t), intent(inout) :: t
    !> The column's values in the rows.
    real(wp), intent(in) :: values(:)
    !> The input coordinate of each row.
    real(wp), intent(in) :: at(:)
    !> The column's value and the input coordinate in the row before the first.
    real(wp), intent(in) :: last, before
    real(wp) :: v, x, last_v, last_at, term
    integer :: k
    last_v = last
    last_at = before
    do k = 1, size(values)
      v = values(k)
      x = at(k)
      term = (v + last_v) * (x - last_at)
      if (.not. abs(term) < tiny_term) t%area2_scaled = t%area2_scaled + (v * value_scale + last_v * value_scale) * &
                                                       (x * step_scale - last_at * step_scale)
      last_v = v
      last_at = x
    end do
  end subroutine scaled_area

  !> Whether the driver's work is defined (a driving moment over the input angle in deg, or a
  !> driving force over its coordinate column) and whether its coordinate is the input angle.
  pure subroutine work_kind(table, d, known, in_rad)
    type(step_table_t), intent(in) :: table
    !> The driver's column (0: none).
    integer, intent(in) :: d
    logical, intent(out) :: known, in_rad
    known = .false.
    in_rad = .false.
    if (d == 0) return
    if (table%work_column > 0) then
      known = .true.
    else if (table%columns(d)%kind == col_moment .and. table%input_column > 0) then
      if (table%columns(table%input_column)%unit /= "deg") return
      known = .true.
      in_rad = .true.
    end if
  end subroutine work_kind

  !> Extremes and mean of column `c` over the rows tallied (at least one). The mean is the
  !> integral over the input angle divided by the angle covered (trapezoid rule; over a
  !> full turn tabulated at 0 and 360 deg this is the cycle average), or the arithmetic
  !> mean of the rows when there is no input angle or it does not move.
  pure function column_stats(table, c) result(s)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Column index.
    integer, intent(in) :: c
    type(column_stats_t) :: s
    real(wp) :: span
    integer :: n
    n = table%run_tally%rows
    associate (t => table%run_tally%columns(c))
      s%max = t%max
      s%min = t%min
      s%max_row = t%max_row
      s%min_row = t%min_row
      s%max_at = t%max_at
      s%min_at = t%min_at
      s%mean = t%total / real(max(1, t%count), wp)
      if (.not. ieee_is_finite(s%mean)) s%mean = t%total_scaled / real(max(1, t%count), wp) / value_scale
      if (table%input_column > 0 .and. n > 1) then
        span = table%run_tally%last_at - table%run_tally%first_at
        ! rows left out (void): over the stretches between rows counted
        if (t%count < n) span = t%span
        if (span /= 0.0_wp) then
          s%mean = 0.5_wp * t%area2 / span
          if (.not. ieee_is_finite(s%mean)) then
            ! the sums overflowed (values near the largest real): the scaled ones
            span = table%run_tally%last_at * step_scale - table%run_tally%first_at * step_scale
            if (t%count < n) span = t%span * step_scale
            if (span /= 0.0_wp) s%mean = 0.5_wp * (t%area2_scaled / span) / value_scale
          end if
        end if
      end if
    end associate
  end function column_stats

  !> Work of the driver over the run, J: the integral of the driving moment over the input
  !> angle in rad (M1 dphi1), or of the driving force over its coordinate column (F2 ds),
  !> taken from the first row to the last (trapezoid rule). Over a tabulated full turn this
  !> is the work per cycle; over a part of a turn, the work of that part only. `known` is
  !> false when the driver has no such coordinate (gears, cams).
  pure subroutine drive_work(table, work, known)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The work, J.
    real(wp), intent(out) :: work
    !> Whether the work is defined for this mechanism.
    logical, intent(out) :: known
    integer :: d
    logical :: in_rad
    work = 0.0_wp
    known = .false.
    if (.not. allocated(table%driver) .or. table%run_tally%rows == 0) return
    d = table%column_index(table%driver)
    call work_kind(table, d, known, in_rad)
    if (known) work = 0.5_wp * table%run_tally%work2
    if (known .and. .not. ieee_is_finite(work)) then
      ! the sum overflowed: the scaled one (still not finite when the work itself is not)
      work = 0.5_wp * table%run_tally%work2_scaled / value_scale / step_scale
    end if
  end subroutine drive_work

  !> A warning when the input step exceeds `coarse_step_limit` and the largest value of a
  !> force column lies within one step of a row where an applied load switches on or off:
  !> the true peak may lie between the rows and be missed. Unallocated otherwise.
  pure subroutine coarse_step_warning(table, warning)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The warning text.
    character(len=:), allocatable, intent(out) :: warning
    real(wp) :: step
    integer :: n, c, k, edge
    character(len=:), allocatable :: names, first_text
    n = table%run_tally%rows
    if (table%input_column == 0 .or. n < 2 .or. .not. allocated(table%load_changes)) return
    if (size(table%load_changes) /= n) return
    step = table%run_tally%largest_step
    if (.not. step > coarse_step_limit * (1.0_wp + 1.0e-9_wp)) return
    names = ""
    do c = 1, size(table%columns)
      if (.not. table%columns(c)%csv .or. table%columns(c)%kind /= col_force) cycle
      k = table%run_tally%columns(c)%peak_row
      if (.not. table%run_tally%columns(c)%peak > 0.0_wp) cycle
      edge = near_edge(k)
      if (edge == 0) cycle
      if (len(names) == 0) then
        first_text = " (the peak of "//table%columns(c)%name//" = "//brief(table%run_tally%columns(c)%peak)// &
          " "//table%columns(c)%unit//" at "//input_text(k)//", the load switches between "// &
          input_text(edge - 1)//" and "//input_text(edge)//")"
        names = table%columns(c)%name
      else
        names = names//", "//table%columns(c)%name
      end if
    end do
    if (len(names) == 0) return
    warning = "the input step "//brief(step)//" deg is coarser than "// &
      brief(coarse_step_limit)//" deg and a load switches on or off within one step of the peak of "// &
      names//first_text//": the true peak may be missed; rerun with a finer step (e.g. --set "// &
      step_variable()//"=0.5) to check"
  contains
    !> Row e (2..n, or 1 for the wrap from the last row) with load_changes(e) whose interval
    !> [e-1, e] touches row k; 0 when none.
    pure integer function near_edge(k)
      integer, intent(in) :: k
      near_edge = 0
      if (table%load_changes(k) .and. k > 1) then
        near_edge = k
      else if (k < n) then
        if (table%load_changes(k + 1)) near_edge = k + 1
      end if
    end function near_edge
    !> "phi1 = 90 deg" of row j (a row next to a load edge: its input coordinate was kept).
    pure function input_text(j) result(t)
      integer, intent(in) :: j
      character(len=:), allocatable :: t
      real(wp) :: x
      integer :: i
      x = 0.0_wp
      do i = 1, size(table%run_tally%edge_points)
        if (table%run_tally%edge_points(i)%row == j) x = table%run_tally%edge_points(i)%at
      end do
      t = table%columns(table%input_column)%name//" = "//brief(x)//" "//table%columns(table%input_column)%unit
    end function input_text
    !> The deck variable of the step: dphi, or dphi3 for an input phi3...
    pure function step_variable() result(t)
      character(len=:), allocatable :: t
      t = "dphi"
      if (lower(table%columns(table%input_column)%name) == "phi3rel") t = "dphi3"
    end function step_variable
  end subroutine coarse_step_warning

  !> A warning when the steps miss the peak of a load table: a point of the table that is a
  !> local extreme (above or below both neighbouring points) lies strictly between the
  !> positions of two consecutive steps, and the load there differs from the load at both
  !> steps by more than table_peak_share of the table's range (largest - smallest value). The
  !> worst such point (the largest of the two differences' smaller) is named. Unallocated
  !> when the steps catch every peak. Steps whose positions jump by more than half the
  !> table's span (the wrap of an angle past the table's end) enclose no point.
  pure subroutine table_peak_warning(name, unit, x, v, q, abscissa, input_name, input_unit, input, step_name, warning)
    !> The table's deck variable ("force(1)%table") and the load's unit ("N").
    character(*), intent(in) :: name, unit
    !> The table's positions (increasing) and values.
    real(wp), intent(in) :: x(:), v(:)
    !> Every step's position in the table's abscissa.
    real(wp), intent(in) :: q(:)
    !> The abscissa as a message names a position ("phi1 =", "the angle of link 3 ="), with its unit
    !> ("deg", "m").
    character(*), intent(in) :: abscissa(2)
    !> The input coordinate's name and unit ("phi1", "deg") and its value at every step.
    character(*), intent(in) :: input_name, input_unit
    real(wp), intent(in) :: input(:)
    !> The deck variable of the step ("dphi").
    character(*), intent(in) :: step_name
    character(len=:), allocatable, intent(out) :: warning
    real(wp) :: range, tol, lo, hi, va, vb, miss, worst
    integer :: np, k, j, jw, kw
    np = size(x)
    if (np < 3 .or. size(q) < 2) return
    range = maxval(v) - minval(v)
    if (.not. range > 0.0_wp) return
    tol = 1.0e-9_wp * max(x(np) - x(1), abs(x(1)), abs(x(np)))
    worst = 0.0_wp
    jw = 0
    kw = 0
    do k = 1, size(q) - 1
      lo = min(q(k), q(k + 1))
      hi = max(q(k), q(k + 1))
      if (hi - lo > 0.5_wp * (x(np) - x(1))) cycle
      j = first_above(lo + tol)
      if (j == 0) cycle
      va = at(q(k))
      vb = at(q(k + 1))
      do while (j < np)
        if (.not. x(j) < hi - tol) exit
        if (j > 1) then
          if ((v(j) > v(j - 1) .and. v(j) > v(j + 1)) .or. (v(j) < v(j - 1) .and. v(j) < v(j + 1))) then
            miss = min(abs(v(j) - va), abs(v(j) - vb))
            if (miss > table_peak_share * range .and. miss > worst) then
              worst = miss
              jw = j
              kw = k
            end if
          end if
        end if
        j = j + 1
      end do
    end do
    if (jw == 0) return
    warning = name//": its point at "//trim(abscissa(1))//" "//brief(x(jw))//" "//trim(abscissa(2))//" ("//brief(v(jw))//" "// &
      unit//", a local "//merge("maximum", "minimum", v(jw) > v(jw - 1))//") lies between the steps at "// &
      input_name//" = "//brief(input(kw))//" "//input_unit//" and "//input_name//" = "//brief(input(kw + 1))//" "// &
      input_unit//", where the load is "//brief(at(q(kw)))//" "//unit//" and "//brief(at(q(kw + 1)))//" "//unit// &
      ": the steps miss the load's peak and the forces it causes; rerun with a finer step (e.g. --set "// &
      step_name//"=0.5) or put a step on the point"
  contains
    !> The first point above position y (binary search), 0 when none.
    pure integer function first_above(y)
      real(wp), intent(in) :: y
      integer :: a, b, m
      first_above = 0
      if (.not. x(np) > y) return
      a = 0
      b = np
      do while (b - a > 1)
        m = (a + b) / 2
        if (x(m) > y) then
          b = m
        else
          a = m
        end if
      end do
      first_above = b
    end function first_above
    !> The table's value at position y (linear between the points; the end values outside).
    pure real(wp) function at(y)
      real(wp), intent(in) :: y
      integer :: i
      i = first_above(y)
      if (i == 0) then
        at = v(np)
      else if (i == 1) then
        at = v(1)
      else
        at = v(i - 1) + (v(i) - v(i - 1)) * (y - x(i - 1)) / (x(i) - x(i - 1))
      end if
    end function at
  end subroutine table_peak_warning

  !> x for a message: two decimals without trailing zeros ("5342.17", "120", "0.5"), or
  !> exponent form for very large or small magnitudes.
  pure function brief(x) result(t)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: t
    character(len=32) :: buf
    integer :: n
    if (abs(x) >= 1.0e9_wp .or. (abs(x) < 0.01_wp .and. x /= 0.0_wp)) then
      t = trimmed_es(x, 3)
      return
    end if
    write (buf, '(f0.2)') x
    t = trim(adjustl(buf))
    if (t(1:1) == ".") t = "0"//t
    if (t(1:min(2, len(t))) == "-.") t = "-0"//t(2:)
    n = len(t)
    do while (t(n:n) == "0")
      n = n - 1
    end do
    if (t(n:n) == ".") n = n - 1
    t = t(1:n)
  end function brief

  !> Summary CSV header: the override names, then rows and the input range, then per
  !> summarized column NAME_max, NAME_max_at, NAME_min, NAME_min_at, NAME_mean, then
  !> work_DRIVER when the work is defined.
  pure function summary_header(table, kinematics) result(line)
    !> The results of one run (columns and overrides; the rows are not used).
    type(step_table_t), intent(in) :: table
    !> Whether the kinematics columns are summarized too (--kinematics).
    logical, intent(in) :: kinematics
    character(len=:), allocatable :: line
    character(len=:), allocatable :: at
    real(wp) :: work
    logical :: known
    integer :: i, c
    line = override_cells(table, 1)
    if (table%single_record) then
      line = line//record_cells(table, 1)
      return
    end if
    line = line//"rows"
    if (allocated(table%void_flags)) line = line//",rows_left_out"
    at = "row"
    if (table%input_column > 0) then
      at = table%columns(table%input_column)%name
      line = line//","//at//"_first,"//at//"_last"
    end if
    do c = 1, size(table%columns)
      if (.not. summarized(table, c, kinematics)) cycle
      associate (name => table%columns(c)%name)
        line = line//","//name//"_max,"//name//"_max_at,"//name//"_min,"//name//"_min_at,"//name//"_mean"
      end associate
    end do
    call drive_work(table, work, known)
    if (known) line = line//",work_"//table%driver
    associate (records => table%dynamics_records())
      do i = 1, size(records)
        if (records(i)%kind == echo_text_kind) cycle
        line = line//","//dynamics_prefix//records(i)%name
      end do
    end associate
  end function summary_header

  !> Summary CSV row of a run (the columns of `summary_header`): override values as given,
  !> then summary_values, numbers at full precision (as the CSV), whole numbers as such.
  pure function summary_row(table, kinematics) result(line)
    !> The results of one run (at least one row tallied).
    type(step_table_t), intent(in) :: table
    !> Whether the kinematics columns are summarized too (--kinematics).
    logical, intent(in) :: kinematics
    character(len=:), allocatable :: line
    real(wp), allocatable :: values(:)
    logical, allocatable :: whole(:)
    integer :: i
    line = override_cells(table, 2)
    if (table%single_record) then
      line = line//record_cells(table, 2)
      return
    end if
    call summary_values(table, kinematics, values, whole)
    do i = 1, size(values)
      if (i > 1) line = line//","
      line = line//cell_number(values(i), whole(i))
    end do
  end function summary_row

  !> The numbers of a run's summary row after its overrides, in the order of
  !> `summary_header`: rows (and rows left out), the first and last input coordinate, per
  !> summarized column its largest value and where ("_at": the input coordinate, or the row
  !> number without one), its smallest and where, its mean; the driver's work; the dynamics
  !> figures (a one-record run: its record's values, as record_cells). `whole` marks the whole
  !> numbers (counts, rows, the extremes of a flag or count column), written as such.
  pure subroutine summary_values(table, kinematics, values, whole)
    !> The results of one run (at least one row tallied).
    type(step_table_t), intent(in) :: table
    !> Whether the kinematics columns are summarized too (--kinematics).
    logical, intent(in) :: kinematics
    !> The numbers.
    real(wp), allocatable, intent(out) :: values(:)
    !> Which of them are whole numbers.
    logical, allocatable, intent(out) :: whole(:)
    type(column_stats_t) :: s
    type(echo_record_t), allocatable :: records(:)
    real(wp) :: work
    logical :: known, at_whole
    integer :: i, c, n
    if (table%single_record) then
      ! the record's own values, as record_cells writes them
      associate (cols => record_columns(table))
        values = table%rows(cols, 1)
        whole = [(table%is_whole(cols(i)), i = 1, size(cols))]
      end associate
      return
    end if
    n = 1
    if (allocated(table%void_flags)) n = n + 1
    if (table%input_column > 0) n = n + 2
    do c = 1, size(table%columns)
      if (summarized(table, c, kinematics)) n = n + 5
    end do
    call drive_work(table, work, known)
    if (known) n = n + 1
    allocate (records(0)) ! defined before the assignment (gcc's -Wmaybe-uninitialized)
    records = table%dynamics_records()
    n = n + count(records(:)%kind /= echo_text_kind)
    allocate (values(n), whole(n))
    n = 0
    call add(values, whole, n, real(table%run_tally%rows, wp), .true.)
    if (allocated(table%void_flags)) call add(values, whole, n, real(table%run_tally%void_rows, wp), .true.)
    if (table%input_column > 0) then
      call add(values, whole, n, table%run_tally%first_at, .false.)
      call add(values, whole, n, table%run_tally%last_at, .false.)
    end if
    at_whole = table%input_column == 0
    do c = 1, size(table%columns)
      if (.not. summarized(table, c, kinematics)) cycle
      s = column_stats(table, c)
      call add(values, whole, n, s%max, table%is_whole(c))
      call add(values, whole, n, at_value(s%max_row, s%max_at), at_whole)
      call add(values, whole, n, s%min, table%is_whole(c))
      call add(values, whole, n, at_value(s%min_row, s%min_at), at_whole)
      call add(values, whole, n, s%mean, .false.)
    end do
    if (known) call add(values, whole, n, work, .false.)
    do i = 1, size(records)
      if (records(i)%kind == echo_text_kind) cycle
      call add(values, whole, n, records(i)%values(1), .false.)
    end do
  contains
    !> values(n + 1) = x, whole(n + 1) = is_whole; n advanced.
    pure subroutine add(values, whole, n, x, is_whole)
      real(wp), intent(inout) :: values(:)
      logical, intent(inout) :: whole(:)
      integer, intent(inout) :: n
      real(wp), intent(in) :: x
      logical, intent(in) :: is_whole
      n = n + 1
      values(n) = x
      whole(n) = is_whole
    end subroutine add
    !> Where an extreme is: the input coordinate, or the row number without one.
    pure real(wp) function at_value(k, x)
      integer, intent(in) :: k
      real(wp), intent(in) :: x
      if (table%input_column > 0) then
        at_value = x
      else
        at_value = real(k, wp)
      end if
    end function at_value
  end subroutine summary_values

  !> The columns of a one-record run's summary: its CSV columns but those named as an
  !> override (the override's own column comes first).
  pure function record_columns(table) result(cols)
    !> The results of one run (one row).
    type(step_table_t), intent(in) :: table
    integer, allocatable :: cols(:)
    integer :: c, i
    allocate (cols(0))
    columns: do c = 1, size(table%columns)
      if (.not. table%columns(c)%csv) cycle columns
      if (allocated(table%overrides)) then
        do i = 1, size(table%overrides)
          if (override_part(table%overrides(i), 1) == table%columns(c)%name) cycle columns
        end do
      end if
      cols = [cols, c]
    end do columns
  end function record_columns

  !> The CSV cells of a one-record run (table%single_record): its columns' names (part 1, the
  !> header) or its values (part 2, the row), comma-separated; a column named as an override
  !> is not repeated.
  pure function record_cells(table, part) result(line)
    !> The results of one run (one row).
    type(step_table_t), intent(in) :: table
    !> 1: names, 2: values.
    integer, intent(in) :: part
    character(len=:), allocatable :: line
    integer :: i
    line = ""
    associate (cols => record_columns(table))
      do i = 1, size(cols)
        if (i > 1) line = line//","
        if (part == 1) then
          line = line//table%columns(cols(i))%name
        else
          line = line//cell_number(table%rows(cols(i), 1), table%is_whole(cols(i)))
        end if
      end do
    end associate
  end function record_cells

  !> The CSV cells of the run's overrides (NAME=VALUE), each followed by a comma: their
  !> names (part 1, the header) or their values (part 2, the row).
  pure function override_cells(table, part) result(line)
    !> The results of one run.
    type(step_table_t), intent(in) :: table
    !> 1: names, 2: values.
    integer, intent(in) :: part
    character(len=:), allocatable :: line
    line = ""
    if (.not. allocated(table%overrides)) return
    line = override_fields(table%overrides, part)
  end function override_cells

  !> The summary's cells of overrides "NAME=VALUE" (as given; blank padding dropped), each
  !> followed by a comma: the names (part 1) or the values (part 2). A variable set again by
  !> a later override has one column, the later one's (it wins in the deck too).
  pure function override_fields(overrides, part) result(line)
    !> The overrides, in command-line order.
    character(*), intent(in) :: overrides(:)
    !> 1: names, 2: values.
    integer, intent(in) :: part
    character(len=:), allocatable :: line
    logical :: has(size(overrides))
    integer :: i
    line = ""
    has = override_has_column(overrides)
    do i = 1, size(overrides)
      if (has(i)) line = line//csv_field(override_part(overrides(i), part))//","
    end do
  end function override_fields

  !> Which overrides "NAME=VALUE" have a column of their own in a summary: those whose
  !> variable no later override sets again (the later one wins, in the deck too).
  pure function override_has_column(overrides) result(has)
    !> The overrides, in command-line order.
    character(*), intent(in) :: overrides(:)
    logical :: has(size(overrides))
    integer :: i, j
    has = .true.
    do i = 1, size(overrides)
      do j = i + 1, size(overrides)
        if (same_name(override_part(overrides(i), 1), override_part(overrides(j), 1))) then
          has(i) = .false.
          exit
        end if
      end do
    end do
  contains
    !> Namelist designators compared as the READ does: case and blanks do not count.
    pure logical function same_name(a, b)
      character(*), intent(in) :: a, b
      same_name = without_blanks(lower(a)) == without_blanks(lower(b))
    end function same_name
  end function override_has_column

  !> Part 1 (the name) or 2 (the value) of "NAME=VALUE" (blank padding dropped).
  pure function override_part(text, part) result(t)
    character(*), intent(in) :: text
    integer, intent(in) :: part
    character(len=:), allocatable :: t
    integer :: eq
    eq = index(text, "=")
    if (part == 1) then
      t = text(1:eq - 1)
    else
      t = trim(text(eq + 1:))
    end if
  end function override_part

end module kinetostat_summary
