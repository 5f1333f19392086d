!> Small string helpers: numbers to trimmed text, lower case.
module kinetostat_text
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: real_str, int_str, lower

  !> Format of a real in a message: shortest general form with 10 significant digits.
  character(*), parameter :: real_msg_fmt = '(g0.10)'

contains

  !> A real as trimmed text (for messages).
  pure function real_str(x) result(s)
    !> Value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=64) :: buf
    write (buf, real_msg_fmt) x
    s = trim(adjustl(buf))
  end function real_str

  !> An integer as trimmed text.
  pure function int_str(i) result(s)
    !> Value.
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function int_str

  !> ASCII lower case.
  pure function lower(s) result(t)
    !> Any text.
    character(*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
    end do
  end function lower

end module kinetostat_text
