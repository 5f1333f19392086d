!> Rows of an output formatted in parallel: with OpenMP and more than one thread
!> (OMP_NUM_THREADS > 1), the rows are cut into blocks, each block formatted into a buffer of
!> its own by one thread, and the buffers appended in row order, so the text is byte for
!> byte the one a single thread writes. With one thread (or without OpenMP) the rows go
!> straight into the output.
module kinetostat_row_blocks
  !$ use omp_lib, only: omp_get_max_threads
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: put_row_blocks, worker_count, put_rows_i

  !> Fewest rows worth a thread: below it the rows go out serially.
  integer, parameter :: min_rows_per_thread = 256
  !> Blocks per thread (more, smaller blocks even out the threads' loads).
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
  end interface

contains

  !> Threads OpenMP would use (1 without OpenMP).
  integer function worker_count()
    worker_count = 1
    !$ worker_count = omp_get_max_threads()
  end function worker_count

  !> Rows 1 to `n_rows` into `out`, formatted by `put_rows` in blocks (in parallel with
  !> more than one thread), in row order.
  subroutine put_row_blocks(n_rows, put_rows, out)
    !> Number of rows.
    integer, intent(in) :: n_rows
    !> Formats a range of rows; it must only read shared data (it runs in several threads).
    procedure(put_rows_i) :: put_rows
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    type(text_buffer_t), allocatable :: parts(:)
    integer :: threads, n_blocks, b
    threads = min(worker_count(), n_rows / min_rows_per_thread)
    if (threads <= 1) then
      call put_rows(1, n_rows, out)
      return
    end if
    n_blocks = min(n_rows, blocks_per_thread * threads)
    allocate (parts(n_blocks))
    !$omp parallel do schedule(dynamic, 1) num_threads(threads)
    do b = 1, n_blocks
      call put_rows(block_first(b), block_first(b + 1) - 1, parts(b))
    end do
    !$omp end parallel do
    do b = 1, n_blocks
      if (parts(b)%length > 0) call out%append(parts(b)%data(1:parts(b)%length))
      if (allocated(parts(b)%data)) deallocate (parts(b)%data)
    end do
  contains
    !> First row of block `i` (block n_blocks + 1 starts after the last row).
    pure integer function block_first(i)
      integer, intent(in) :: i
      block_first = 1 + int(int(i - 1, int64) * n_rows / n_blocks)
    end function block_first
  end subroutine put_row_blocks

end module kinetostat_row_blocks
