!> The rows of a run a drawing needs, kept block by block as the run goes, so that a drawing
!> of a run of any length needs the memory of one block and of what it draws, not of every
!> step:
!> - `--at K` (the mechanism, its plans, DXF, JSON --plans): row K, the run's first row,
!>   `at_samples` rows spread evenly over the run (what the drawing tells of the whole run,
!>   such as which links turn together, it reads from them: every row of a short run) and,
!>   for each given direction through a point (a slider's guide), the rows where the point
!>   is farthest back and forth along it (its travel, which the drawing shows);
!> - the SVG sheet: every row of a run of up to `all_rows_limit` rows; of a longer one, per
!>   bucket of rows (sheet_buckets equal stretches of the run's row numbers) the rows of the
!>   smallest and the largest value of every column (`bucket_extremes`), so that a curve
!>   drawn through them keeps the peaks of every series.
!> The kept rows replace the table's rows at the end (`take`); table%row_numbers says which
!> rows of the run they are.
module kinetostat_row_keeper
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, out_of_memory
  use kinetostat_text, only: int_str
  use kinetostat_step_table, only: step_table_t
  implicit none
  private
  public :: row_keeper_t, bucket_extremes, all_rows_limit, sheet_buckets

  !> A run of up to this many rows is drawn through every row.
  integer, parameter :: all_rows_limit = 4096
  !> --at K: rows kept spread evenly over the run (first and last included).
  integer, parameter :: at_samples = 33
  !> Buckets of a longer run on the SVG sheet: min and max of each column per bucket. A
  !> curve of one series draws sheet_buckets buckets (2 points each: 4096 points), of two
  !> (a hodograph's x and y) sheet_buckets/2: these divide sheet_buckets, so the extremes a
  !> curve needs are among the rows kept.
  integer, parameter :: sheet_buckets = 2048

  !> What to keep of a run's rows, and what was kept.
  type :: row_keeper_t
    !> Keep the extremes per bucket (the SVG sheet) rather than the row of --at K.
    logical :: by_buckets = .false.
    !> --at K: the run's row to keep.
    integer :: at_row = 0
    !> Directions: the columns of a point's x and y (0: unknown point, nothing to keep).
    integer, allocatable :: cx(:), cy(:)
    !> Directions: the unit vectors (2, directions).
    real(wp), allocatable :: u(:, :)
    !> Rows of the run.
    integer :: total = 0
    !> The kept rows (columns, kept), in the run's order, and their run row numbers.
    real(wp), allocatable :: rows(:, :)
    !> Run row numbers of the kept rows.
    integer, allocatable :: numbers(:)
    !> Kept rows in use.
    integer :: count = 0
    !> The first `closed` kept rows are final (buckets that ended); the rest may still be
    !> replaced by rows of the next block.
    integer :: closed = 0
  contains
    procedure :: keep_at, keep_buckets, add, take
  end type row_keeper_t

contains

  !> Keep row `k` of the run and, for each direction `u(:, i)` through the point with the
  !> columns cx(i), cy(i), the rows of the smallest and largest u . (x, y).
  pure subroutine keep_at(self, k, cx, cy, u)
    class(row_keeper_t), intent(inout) :: self
    !> Run row.
    integer, intent(in) :: k
    !> Columns of each direction's point (0: none).
    integer, intent(in) :: cx(:), cy(:)
    !> Unit vectors (2, directions).
    real(wp), intent(in) :: u(:, :)
    self%by_buckets = .false.
    self%at_row = k
    self%cx = cx
    self%cy = cy
    self%u = u
  end subroutine keep_at

  !> Keep what the SVG sheet draws (see the module's note).
  pure subroutine keep_buckets(self)
    class(row_keeper_t), intent(inout) :: self
    self%by_buckets = .true.
  end subroutine keep_buckets

  !> The rows of the block now in `table` (its rows row_offset+1 ..) into the kept ones.
  subroutine add(self, table, error)
    class(row_keeper_t), intent(inout) :: self
    type(step_table_t), intent(in) :: table
    !> The kept rows do not fit in memory (exit 2).
    type(error_t), allocatable, intent(out) :: error
    real(wp), allocatable :: pool(:, :)
    integer, allocatable :: numbers(:), keep(:)
    integer :: nc, n_open, n_block, k, last_bucket, first_open, stat
    self%total = table%run_rows()
    nc = size(table%columns)
    n_block = table%row_count()
    if (n_block == 0) return
    ! the candidates: the kept rows still open, then the block's rows
    n_open = self%count - self%closed
    allocate (pool(nc, n_open + n_block), stat=stat)
    if (stat == 0) allocate (numbers(n_open + n_block), stat=stat)
    if (stat /= 0) then
      call no_room(nc, n_open + n_block, error)
      return
    end if
    if (n_open > 0) then
      pool(:, 1:n_open) = self%rows(:, self%closed + 1:self%count)
      numbers(1:n_open) = self%numbers(self%closed + 1:self%count)
    end if
    pool(:, n_open + 1:) = table%rows
    do k = 1, n_block
      numbers(n_open + k) = table%row_offset + k
    end do
    self%count = self%closed
    if (.not. self%by_buckets) then
      call at_rows(keep)
      call append(keep, error)
      return
    end if
    if (self%total <= all_rows_limit) then
      call append([(k, k=1, size(numbers))], error)
      self%closed = self%count
      return
    end if
    call bucket_extremes(transpose(pool), numbers, self%total, sheet_buckets, keep)
    ! the rows of buckets that end in this block are final; the last bucket of the block
    ! stays open unless the run ends here
    last_bucket = bucket_of(numbers(size(numbers)), self%total, sheet_buckets)
    first_open = size(keep) + 1
    if (numbers(size(numbers)) < self%total) then
      do while (first_open > 1)
        if (bucket_of(numbers(keep(first_open - 1)), self%total, sheet_buckets) /= last_bucket) exit
        first_open = first_open - 1
      end do
    end if
    call append(keep(1:first_open - 1), error)
    if (allocated(error)) return
    self%closed = self%count
    call append(keep(first_open:), error)
  contains
    !> --at: the run's first row, row at_row and each direction's extreme rows, from `pool`
    !> (the first on a tie), in the run's order.
    pure subroutine at_rows(keep)
      integer, allocatable, intent(out) :: keep(:)
      logical :: taken(size(numbers))
      real(wp) :: s(size(numbers))
      integer :: i
      taken = numbers == 1 .or. numbers == self%at_row
      do i = 1, size(numbers)
        taken(i) = taken(i) .or. is_sample(numbers(i))
      end do
      do i = 1, size(self%cx)
        if (self%cx(i) == 0 .or. self%cy(i) == 0) cycle
        s = self%u(1, i) * pool(self%cx(i), :) + self%u(2, i) * pool(self%cy(i), :)
        taken(minloc(s, dim=1)) = .true.
        taken(maxloc(s, dim=1)) = .true.
      end do
      keep = pack([(i, i=1, size(numbers))], taken)
    end subroutine at_rows

    !> Whether run row r is one of the at_samples rows spread evenly over the run.
    pure logical function is_sample(r)
      integer, intent(in) :: r
      integer :: j
      integer(int64) :: below
      is_sample = .true.
      if (self%total <= at_samples) return
      ! sample j (0 .. at_samples - 1) is row 1 + floor(j (total - 1) / (at_samples - 1))
      below = (int(r - 1, int64) * (at_samples - 1)) / (self%total - 1)
      do j = int(below), min(int(below) + 1, at_samples - 1)
        if (1 + (int(j, int64) * (self%total - 1)) / (at_samples - 1) == r) return
      end do
      is_sample = .false.
    end function is_sample

    !> Candidates `which` appended to the kept rows (growing them as needed).
    subroutine append(which, error)
      integer, intent(in) :: which(:)
      type(error_t), allocatable, intent(out) :: error
      real(wp), allocatable :: grown(:, :)
      integer, allocatable :: grown_numbers(:)
      integer :: need, capacity, stat
      need = self%count + size(which)
      capacity = 0
      if (allocated(self%numbers)) capacity = size(self%numbers)
      if (need > capacity) then
        capacity = max(need, 2 * capacity, 64)
        allocate (grown(nc, capacity), stat=stat)
        if (stat == 0) allocate (grown_numbers(capacity), stat=stat)
        if (stat /= 0) then
          call no_room(nc, capacity, error)
          return
        end if
        if (self%count > 0) then
          grown(:, 1:self%count) = self%rows(:, 1:self%count)
          grown_numbers(1:self%count) = self%numbers(1:self%count)
        end if
        call move_alloc(grown, self%rows)
        call move_alloc(grown_numbers, self%numbers)
      end if
      self%rows(:, self%count + 1:need) = pool(:, which)
      self%numbers(self%count + 1:need) = numbers(which)
      self%count = need
    end subroutine append
  end subroutine add

  !> The kept rows in place of the table's rows (table%row_numbers says which they are).
  pure subroutine take(self, table, error)
    class(row_keeper_t), intent(inout) :: self
    type(step_table_t), intent(inout) :: table
    !> The rows do not fit in memory (exit 2).
    type(error_t), allocatable, intent(out) :: error
    integer :: stat
    if (allocated(table%rows)) deallocate (table%rows)
    allocate (table%rows(size(table%columns), self%count), stat=stat)
    if (stat /= 0) then
      call no_room(size(table%columns), self%count, error)
      return
    end if
    if (self%count > 0) table%rows = self%rows(:, 1:self%count)
    table%row_numbers = self%numbers(1:self%count)
    table%total_rows = self%total
    ! the table reads as the run's last block (row_numbers say which rows it holds)
    table%row_offset = self%total - self%count
    deallocate (self%rows, self%numbers)
    self%count = 0
    self%closed = 0
  end subroutine take

  !> The rows of a long series a curve is drawn through: of each of `buckets` equal
  !> stretches of the run's rows (by run row number; bucket_of), the rows of the smallest
  !> and the largest value of every column of `values` (the first such row on a tie), in
  !> order: at most 2 * buckets * columns rows, and the peaks of every column survive.
  pure subroutine bucket_extremes(values, numbers, total, buckets, keep)
    !> One row per row of the series, one column per drawn coordinate.
    real(wp), intent(in) :: values(:, :)
    !> The run's row number of each row of `values` (increasing).
    integer, intent(in) :: numbers(:)
    !> Rows of the run.
    integer, intent(in) :: total
    !> Buckets of the run.
    integer, intent(in) :: buckets
    !> Indices of the rows kept (into `values`), increasing.
    integer, allocatable, intent(out) :: keep(:)
    logical :: taken(size(numbers))
    integer :: first, last, b, c, n
    n = size(numbers)
    taken = .false.
    first = 1
    do while (first <= n)
      b = bucket_of(numbers(first), total, buckets)
      last = first
      do while (last < n)
        if (bucket_of(numbers(last + 1), total, buckets) /= b) exit
        last = last + 1
      end do
      do c = 1, size(values, 2)
        taken(first - 1 + minloc(values(first:last, c), dim=1)) = .true.
        taken(first - 1 + maxloc(values(first:last, c), dim=1)) = .true.
      end do
      first = last + 1
    end do
    keep = pack([(b, b=1, n)], taken)
  end subroutine bucket_extremes

  !> The bucket (1 .. buckets) of run row r of `total`: buckets of equal numbers of rows
  !> (bucket b holds the rows with floor((r - 1) buckets / total) = b - 1; a bucket of
  !> buckets/m is the union of m consecutive buckets of `buckets`).
  pure integer function bucket_of(r, total, buckets)
    integer, intent(in) :: r, total, buckets
    bucket_of = int(int(r - 1, int64) * buckets / max(total, 1)) + 1
  end function bucket_of

  !> The error of rows that do not fit in memory.
  pure subroutine no_room(columns, rows, error)
    integer, intent(in) :: columns, rows
    type(error_t), allocatable, intent(out) :: error
    call out_of_memory(error, "the "//int_str(rows)//" rows of "//int_str(columns)//" columns a drawing keeps", &
      8_int64 * rows * columns)
  end subroutine no_room

end module kinetostat_row_keeper
