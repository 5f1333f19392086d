!> A growing block of output text: writers append lines to it, and the CLI writes it out
!> in one piece only after the whole run succeeded (so no output is ever partial).
module kinetostat_text_buffer
  implicit none
  private
  public :: text_buffer_t

  !> Initial capacity, bytes.
  integer, parameter :: initial_capacity = 65536

  !> Lines of text, each ended by a newline.
  type :: text_buffer_t
    !> The bytes; only data(1:length) is in use.
    character(len=:), allocatable :: data
    !> Bytes in use.
    integer :: length = 0
  contains
    procedure :: put
    procedure :: text
  end type text_buffer_t

contains

  !> Append one line (a newline is added).
  pure subroutine put(self, line)
    class(text_buffer_t), intent(inout) :: self
    !> The line, without its newline.
    character(*), intent(in) :: line
    character(len=:), allocatable :: grown
    integer :: need
    need = self%length + len(line) + 1
    if (.not. allocated(self%data)) allocate (character(len=max(initial_capacity, need)) :: self%data)
    if (need > len(self%data)) then
      allocate (character(len=max(need, 2 * len(self%data))) :: grown)
      grown(1:self%length) = self%data(1:self%length)
      call move_alloc(grown, self%data)
    end if
    self%data(self%length + 1:self%length + len(line)) = line
    self%data(need:need) = new_line("a")
    self%length = need
  end subroutine put

  !> The text so far.
  pure function text(self) result(s)
    class(text_buffer_t), intent(in) :: self
    character(len=:), allocatable :: s
    if (allocated(self%data)) then
      s = self%data(1:self%length)
    else
      s = ""
    end if
  end function text

end module kinetostat_text_buffer
