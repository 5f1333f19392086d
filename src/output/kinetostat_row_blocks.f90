!> Rows of an output formatted in parallel: with OpenMP and more than one thread
!> (OMP_NUM_THREADS > 1), the rows are cut into blocks, each block formatted by one thread
!> into a buffer of its own and appended in row order (an OpenMP ordered section, while
!> the other threads format the next blocks), so the text is byte for byte the one a single
!> thread writes and the buffers stay small. With one thread (or without OpenMP) the rows go
!> straight into the output.
module kinetostat_row_blocks
  !$ use omp_lib, only: omp_get_max_threads, omp_get_thread_num
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_step_table, only: step_table_t
  use kinetostat_format, only: put_cells, cell_room
  use kinetostat_decimal, only: put_cell_numbers
  implicit none
  private
  public :: put_row_blocks, put_row_blocks_two, worker_count, row_writer_t, text_sink_t, table_rows_t

  !> Fewest rows worth a thread: below it the rows go out serially.
  integer, parameter :: min_rows_per_thread = 256
  !> Rows of a block: the text of one block per thread is all the memory the parallel
  !> formatting adds (about 3 MB for 2 threads with the kinematics columns).
  integer, parameter :: rows_per_block = 2048
  !> Most room reserved at once, bytes (1 GiB; the buffer grows beyond it as needed).
  integer(int64), parameter :: max_reserve = 1073741824_int64
  !> Blocks per thread at least (more, smaller blocks even out the threads' loads).
  integer, parameter :: blocks_per_thread = 4

  !> What formats rows of an output: a writer extends it with what its rows are made of
  !> (an explicit context, not a procedure of its host: no trampoline, no executable stack).
  type, abstract :: row_writer_t
  contains
    !> Format rows `first` to `last`; it must only read shared data (it runs in several threads).
    procedure(put_rows_i), deferred :: put_rows
  end type row_writer_t

  !> A writer of a step table's rows (the CSV's, the JSON's): the table and the columns it
  !> shows, with how each is written, and how a row is framed: `opening`, the cells with
  !> `separator` between them (`void_cell` in a row without values), then `closing` (after
  !> the run's last row `last_closing`).
  type, extends(row_writer_t) :: table_rows_t
    !> The results (while the writer runs only).
    type(step_table_t), pointer :: table => null()
    !> The table's columns shown, in order.
    integer, allocatable :: columns(:)
    !> Per shown column: a whole number (flag, count).
    logical, allocatable :: whole(:)
    !> Per shown column: no value in a row without values.
    logical, allocatable :: voidable(:)
    !> Text before a row's first cell.
    character(len=:), allocatable :: opening
    !> Text between two cells.
    character(len=:), allocatable :: separator
    !> A cell without a value (a jammed cam follower's forces): never a 0.
    character(len=:), allocatable :: void_cell
    !> Text after a row's last cell, but the run's last row.
    character(len=:), allocatable :: closing
    !> Text after the run's last row's last cell.
    character(len=:), allocatable :: last_closing
  contains
    procedure :: aim => aim_table_rows
    procedure :: row_room => table_row_room
    procedure :: put_rows => put_table_rows
  end type table_rows_t

  !> What takes the text of an output as its rows are formatted (e.g. the spool's file).
  type, abstract :: text_sink_t
  contains
    !> Takes the text written so far, in row order (it may move it elsewhere and empty `out`).
    procedure(take_i), deferred :: take
    !> Takes the text so far and then a part after it (by default: the part appended to the
    !> text, then `take`; a sink that writes the text out may write the part straight from
    !> its own buffer, without the copy).
    procedure :: take_part
  end type text_sink_t

  abstract interface
    !> Format rows `first` to `last` into two texts (a section and a second section over
    !> the same rows, which goes after the first; a writer of one section leaves `later`).
    subroutine put_rows_i(self, first, last, out, later)
      import :: row_writer_t, text_buffer_t
      implicit none
      !> The writer and what its rows are made of.
      class(row_writer_t), intent(in) :: self
      !> First and last row.
      integer, intent(in) :: first, last
      !> Where the first section's text goes.
      type(text_buffer_t), intent(inout) :: out
      !> Where the second section's text goes.
      type(text_buffer_t), intent(inout) :: later
    end subroutine put_rows_i

    !> Takes the text written so far, in row order (it may move it elsewhere and empty `out`).
    subroutine take_i(self, out)
      import :: text_sink_t, text_buffer_t
      implicit none
      !> The sink.
      class(text_sink_t), intent(inout) :: self
      !> The text so far.
      type(text_buffer_t), intent(inout) :: out
    end subroutine take_i
  end interface

contains

  !> Aim a table writer at `table` and the columns marked in `shown`, its rows framed by
  !> `opening`, `separator` (`void_cell` for a cell without a value), `closing` and, after
  !> the run's last row, `last_closing`.
  subroutine aim_table_rows(self, table, shown, opening, separator, void_cell, closing, last_closing)
    class(table_rows_t), intent(inout) :: self
    !> The results (the writer keeps a pointer while it runs).
    type(step_table_t), intent(in), target :: table
    !> Per column of the table: whether the output shows it.
    logical, intent(in) :: shown(:)
    !> How a row is framed (see table_rows_t).
    character(*), intent(in) :: opening, separator, void_cell, closing, last_closing
    integer :: c
    self%columns = pack([(c, c = 1, size(shown))], shown)
    allocate (self%whole(size(self%columns)), self%voidable(size(self%columns)))
    do c = 1, size(self%columns)
      self%whole(c) = table%is_whole(self%columns(c))
      self%voidable(c) = table%columns(self%columns(c))%voidable
    end do
    self%table => table
    self%opening = opening
    self%separator = separator
    self%void_cell = void_cell
    self%closing = closing
    self%last_closing = last_closing
  end subroutine aim_table_rows

  !> Room of a row of `n_columns` cells, bytes (its line end counted).
  pure integer function table_row_room(self, n_columns)
    class(table_rows_t), intent(in) :: self
    integer, intent(in) :: n_columns
    table_row_room = n_columns * (cell_room + len(self%separator)) + len(self%opening) + len(self%closing) + 1
  end function table_row_room

  !> Rows `first` to `last`, one line each.
  subroutine put_table_rows(self, first, last, out, later)
    !> The table, its shown columns and the rows' framing.
    class(table_rows_t), intent(in) :: self
    !> First and last row.
    integer, intent(in) :: first, last
    !> Where the rows go.
    type(text_buffer_t), intent(inout) :: out
    !> Unused (a table's rows are one section).
    type(text_buffer_t), intent(inout) :: later
    integer :: k, last_framed
    ! room for every row at once (no copying while the buffer grows; 8 bytes stored past it)
    call out%reserve((last - first + 1) * self%row_room(size(self%columns)) + 8)
    k = first
    if (.not. allocated(self%table%void_flags) .and. len(self%separator) >= 1 .and. len(self%separator) <= 2 .and. &
      len(self%opening) <= 8 .and. len(self%closing) < 8) then
      ! no row without values: whole lines at once, but the run's last row (its own closing)
      last_framed = min(last, max(self%table%total_rows, self%table%row_count()) - self%table%row_offset - 1)
      if (last_framed >= first) then
        call put_cell_numbers(self%table%rows(:, first:last_framed), size(self%table%rows, 1), last_framed - first + 1, &
          self%columns, self%opening, self%separator, self%closing//new_line("a"), out%data, out%length, self%whole)
        k = last_framed + 1
      end if
    end if
    do k = k, last
      if (len(self%opening) > 0) call out%append(self%opening)
      if (self%table%is_void(k) .or. len(self%separator) < 1 .or. len(self%separator) > 2) then
        call put_cells(out, self%table%rows(:, k), self%columns, self%whole, self%voidable, self%table%is_void(k), &
          self%separator, self%void_cell)
      else
        call put_cell_numbers(self%table%rows(:, k), size(self%table%rows, 1), 1, self%columns, "", self%separator, "", &
          out%data, out%length, self%whole)
      end if
      if (self%table%row_offset + k < max(self%table%total_rows, self%table%row_count())) then
        if (len(self%closing) > 0) call out%append(self%closing)
      else
        call out%append(self%last_closing)
      end if
      call out%end_line()
    end do
  end subroutine put_table_rows

  !> The part appended to `out`, then the sink's `take` (text_sink_t's default take_part).
  subroutine take_part(self, out, part)
    !> The sink.
    class(text_sink_t), intent(inout) :: self
    !> The text so far.
    type(text_buffer_t), intent(inout) :: out
    !> The text that comes after it (left as it is).
    type(text_buffer_t), intent(in) :: part
    if (part%length > 0) call out%append(part%data(1:part%length))
    call self%take(out)
  end subroutine take_part

  !> Threads OpenMP would use (1 without OpenMP).
  integer function worker_count()
    worker_count = 1
    !$ worker_count = omp_get_max_threads()
  end function worker_count

  !> Rows 1 to `n_rows` into `out`, formatted by `writer` in blocks (in parallel with
  !> more than one thread), in row order. With `sink`, its `take` gets `out` after every
  !> block appended (in row order, while the other threads format the next blocks), so that
  !> writing the text out overlaps the formatting.
  subroutine put_row_blocks(n_rows, row_room, writer, out, sink)
    !> Number of rows.
    integer, intent(in) :: n_rows
    !> Most bytes a row takes.
    integer, intent(in) :: row_room
    !> Formats a range of rows (one section: nothing goes to its `later`).
    class(row_writer_t), intent(in) :: writer
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    !> Takes the text so far (e.g. to the spool's file).
    class(text_sink_t), intent(inout), optional :: sink
    type(text_buffer_t) :: no_later
    call put_row_blocks_two(n_rows, row_room, writer, out, no_later, sink)
  end subroutine put_row_blocks

  !> put_row_blocks for a layout that writes two sections over the same rows: each block's
  !> text of each section into a buffer of its thread, appended in row order to `out` and to
  !> `later` (`sink`, if given, is called with `out` after each block).
  subroutine put_row_blocks_two(n_rows, row_room, writer, out, later, sink)
    !> Number of rows.
    integer, intent(in) :: n_rows
    !> Most bytes a row takes in `out`.
    integer, intent(in) :: row_room
    !> Formats a range of rows; it must only read shared data (it runs in several threads).
    class(row_writer_t), intent(in) :: writer
    !> Where the first section's text goes.
    type(text_buffer_t), intent(inout) :: out
    !> Where the second section's text goes.
    type(text_buffer_t), intent(inout) :: later
    !> Takes the text of `out` so far (e.g. to the spool's file).
    class(text_sink_t), intent(inout), optional :: sink
    type(text_buffer_t), allocatable :: parts(:), later_parts(:)
    integer :: threads, block_rows, n_blocks, b, me
    threads = min(worker_count(), n_rows / min_rows_per_thread)
    if (threads <= 1) then
      call writer%put_rows(1, n_rows, out, later)
      return
    end if
    if (.not. present(sink)) call out%reserve(int(min(int(n_rows, int64) * row_room, max_reserve)))
    block_rows = min(rows_per_block, (n_rows + blocks_per_thread * threads - 1) / (blocks_per_thread * threads))
    n_blocks = (n_rows + block_rows - 1) / block_rows
    ! one buffer per thread: a thread formats its block, appends it in row order, then the next
    allocate (parts(0:threads - 1), later_parts(0:threads - 1))
    me = 0
    !$omp parallel do schedule(dynamic, 1) ordered num_threads(threads) private(me)
    do b = 1, n_blocks
      !$ me = omp_get_thread_num()
      parts(me)%length = 0
      later_parts(me)%length = 0
      call writer%put_rows((b - 1) * block_rows + 1, min(n_rows, b * block_rows), parts(me), later_parts(me))
      !$omp ordered
      if (present(sink)) then
        call sink%take_part(out, parts(me))
      else if (parts(me)%length > 0) then
        call out%append(parts(me)%data(1:parts(me)%length))
      end if
      if (later_parts(me)%length > 0) call later%append(later_parts(me)%data(1:later_parts(me)%length))
      !$omp end ordered
    end do
    !$omp end parallel do
  end subroutine put_row_blocks_two

end module kinetostat_row_blocks
