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
    !> Bytes the text would have held when it could not grow (out of memory): the text is
    !> lost (emptied, so that writers go on without harm) and the run must stop; 0: none.
    integer :: lost = 0
  contains
    procedure :: put
    procedure :: put_lines
    procedure :: append
    procedure :: end_line
    procedure :: reserve
    procedure :: text
  end type text_buffer_t

contains

  !> Append one line (a newline is added).
  pure subroutine put(self, line)
    class(text_buffer_t), intent(inout) :: self
    !> The line, without its newline.
    character(*), intent(in) :: line
    integer :: need
    need = self%length + len(line) + 1
    call self%reserve(len(line) + 1)
    self%data(self%length + 1:self%length + len(line)) = line
    self%data(need:need) = new_line("a")
    self%length = need
  end subroutine put

  !> Append lines, each without its trailing blanks.
  pure subroutine put_lines(self, lines)
    class(text_buffer_t), intent(inout) :: self
    !> The lines (of one length, blank-padded).
    character(*), intent(in) :: lines(:)
    integer :: i
    do i = 1, size(lines)
      call self%put(trim(lines(i)))
    end do
  end subroutine put_lines

  !> Append text to the current line (no newline).
  pure subroutine append(self, s)
    class(text_buffer_t), intent(inout) :: self
    !> The text.
    character(*), intent(in) :: s
    call self%reserve(len(s))
    self%data(self%length + 1:self%length + len(s)) = s
    self%length = self%length + len(s)
  end subroutine append

  !> End the current line (a newline).
  pure subroutine end_line(self)
    class(text_buffer_t), intent(inout) :: self
    call self%reserve(1)
    self%length = self%length + 1
    self%data(self%length:self%length) = new_line("a")
  end subroutine end_line

  !> Make room for `extra` more bytes after data(1:length) (writers that fill data directly).
  pure subroutine reserve(self, extra)
    class(text_buffer_t), intent(inout) :: self
    !> Bytes needed, beyond the length in use.
    integer, intent(in) :: extra
    character(len=:), allocatable :: grown
    integer :: need, stat
    need = self%length + extra
    stat = 0
    if (.not. allocated(self%data)) then
      allocate (character(len=max(initial_capacity, need)) :: self%data, stat=stat)
    else if (need > len(self%data)) then
      allocate (character(len=max(need, 2 * len(self%data))) :: grown, stat=stat)
      if (stat /= 0) allocate (character(len=need) :: grown, stat=stat)
      if (stat == 0) then
        grown(1:self%length) = self%data(1:self%length)
        call move_alloc(grown, self%data)
      end if
    end if
    if (stat == 0) return
    ! out of memory: the text is dropped (the run stops on `lost`); what is appended next goes
    ! to a buffer just large enough, so that writers filling data directly go on unharmed
    self%lost = max(self%lost, need)
    self%length = 0
    if (allocated(self%data)) deallocate (self%data)
    allocate (character(len=max(1, extra)) :: self%data)
  end subroutine reserve

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
