!> Rows of an output formatted in parallel: with OpenMP and more than one thread
!> (OMP_NUM_THREADS > 1), the rows are cut into blocks, each block formatted into a buffer of
!> its own by one thread, and the buffers appended in row order, so the text is byte for
!> byte the one a single thread writes; blocks go a wave at a time, so the buffers stay
!> small. With one thread (or without OpenMP) the rows go straight into the output.
module kinetostat_row_blocks
  !$ use omp_lib, only: omp_get_max_threads
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: put_row_blocks, put_row_blocks_two, worker_count, put_rows_i, put_rows_two_i

  !> Fewest rows worth a thread: below it the rows go out serially.
  integer, parameter :: min_rows_per_thread = 256
  !> Rows of a block: the text of one wave of blocks (threads * blocks_per_thread of them)
  !> is all the memory the parallel formatting adds (about 6 MB for 2 threads).
  integer, parameter :: rows_per_block = 2048
  !> Most room reserved at once, bytes (1 GiB; the buffer grows beyond it as needed).
  integer(int64), parameter :: max_reserve = 1073741824_int64
  !> Blocks per thread in a wave (more, smaller blocks even out the threads' loads).
  integer, parameter :: blocks_per_thread = 4

  abstract interface
    !> Format rows `first` to `last` into `out`.
    subroutine put_rows_i(first, last, out)
      import :: text_buffer_t
      implicit none
      !> First and last row.
      integer, intent(in) :: first, last
      !> Where the text goes.
      type(text_buffer_t), intent(inout) :: out
    end subroutine put_rows_i

    !> Format rows `first` to `last` into two texts (a section and a second section over
    !> the same rows, which goes after the first).
    subroutine put_rows_two_i(first, last, out, later)
      import :: text_buffer_t
      implicit none
      !> First and last row.
      integer, intent(in) :: first, last
      !> Where the first section's text goes.
      type(text_buffer_t), intent(inout) :: out
      !> Where the second section's text goes.
      type(text_buffer_t), intent(inout) :: later
    end subroutine put_rows_two_i
  end interface

contains

  !> Threads OpenMP would use (1 without OpenMP).
  integer function worker_count()
    worker_count = 1
    !$ worker_count = omp_get_max_threads()
  end function worker_count

  !> Rows 1 to `n_rows` into `out`, formatted by `put_rows` in blocks (in parallel with
  !> more than one thread, a wave of blocks at a time), in row order.
  subroutine put_row_blocks(n_rows, row_room, put_rows, out)
    !> Number of rows.
    integer, intent(in) :: n_rows
    !> Most bytes a row takes (room is made in `out` for all rows at once).
    integer, intent(in) :: row_room
    !> Formats a range of rows; it must only read shared data (it runs in several threads).
    procedure(put_rows_i) :: put_rows
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    type(text_buffer_t) :: no_later
    call put_row_blocks_two(n_rows, row_room, put_both, out, no_later)
  contains
    !> The one section's rows (nothing goes to `later`).
    subroutine put_both(first, last, part, later)
      integer, intent(in) :: first, last
      type(text_buffer_t), intent(inout) :: part
      type(text_buffer_t), intent(inout) :: later
      call put_rows(first, last, part)
    end subroutine put_both
  end subroutine put_row_blocks

  !> put_row_blocks for a layout that writes two sections over the same rows: each block's
  !> text of each section into a buffer of its own, appended in row order to `out` and to
  !> `later`.
  subroutine put_row_blocks_two(n_rows, row_room, put_rows, out, later)
    !> Number of rows.
    integer, intent(in) :: n_rows
    !> Most bytes a row takes in `out` (room is made in `out` for all rows at once).
    integer, intent(in) :: row_room
    !> Formats a range of rows; it must only read shared data (it runs in several threads).
    procedure(put_rows_two_i) :: put_rows
    !> Where the first section's text goes.
    type(text_buffer_t), intent(inout) :: out
    !> Where the second section's text goes.
    type(text_buffer_t), intent(inout) :: later
    type(text_buffer_t), allocatable :: parts(:), later_parts(:)
    integer :: threads, block_rows, n_blocks, wave, first_block, last_block, b
    threads = min(worker_count(), n_rows / min_rows_per_thread)
    if (threads <= 1) then
      call put_rows(1, n_rows, out, later)
      return
    end if
    call out%reserve(int(min(int(n_rows, int64) * row_room, max_reserve)))
    wave = blocks_per_thread * threads
    block_rows = min(rows_per_block, (n_rows + wave - 1) / wave)
    n_blocks = (n_rows + block_rows - 1) / block_rows
    allocate (parts(wave), later_parts(wave))
    do first_block = 1, n_blocks, wave
      last_block = min(n_blocks, first_block + wave - 1)
      !$omp parallel do schedule(dynamic, 1) num_threads(threads)
      do b = first_block, last_block
        parts(b - first_block + 1)%length = 0
        later_parts(b - first_block + 1)%length = 0
        call put_rows((b - 1) * block_rows + 1, min(n_rows, b * block_rows), parts(b - first_block + 1), &
                      later_parts(b - first_block + 1))
      end do
      !$omp end parallel do
      do b = 1, last_block - first_block + 1
        if (parts(b)%length > 0) call out%append(parts(b)%data(1:parts(b)%length))
        if (later_parts(b)%length > 0) call later%append(later_parts(b)%data(1:later_parts(b)%length))
      end do
    end do
  end subroutine put_row_blocks_two

end module kinetostat_row_blocks
