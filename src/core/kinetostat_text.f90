!> Small string helpers: numbers to trimmed text, lower case.
module kinetostat_text
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: real_str, int_str, number_str, lower, upper

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

  !> A deck number as trimmed text: a whole number below 1e15 in magnitude without a
  !> decimal point ("2147483648"), anything else as `real_str` ("1.500000000", "NaN").
  pure function number_str(x) result(s)
    !> Value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=24) :: buf
    if (abs(x) < 1.0e15_wp .and. x == aint(x)) then
      write (buf, '(i0)') int(x, int64)
      s = trim(buf)
    else
      s = real_str(x)
    end if
  end function number_str

  !> An integer as trimmed text (the text of the `i0` edit descriptor), built digit by digit:
  !> an internal WRITE costs ~0.3 us (locale, locks), and column names are built per step.
  pure function int_str(i) result(s)
    !> Value.
    integer, intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    integer(int64) :: v
    integer :: pos
    v = abs(int(i, int64))
    pos = len(buf) + 1
    do
      pos = pos - 1
      buf(pos:pos) = achar(iachar('0') + int(mod(v, 10_int64)))
      v = v / 10_int64
      if (v == 0_int64) exit
    end do
    if (i < 0) then
      pos = pos - 1
      buf(pos:pos) = '-'
    end if
    s = buf(pos:)
  end function int_str

  !> ASCII lower case.
  pure function lower(s) result(t)
    !> Any text.
    character(*), intent(in) :: s
    character(len=len(s)) :: t
    t = shift_letters(s, 'A', 'Z', 32)
  end function lower

  !> ASCII upper case.
  pure function upper(s) result(t)
    !> Any text.
    character(*), intent(in) :: s
    character(len=len(s)) :: t
    t = shift_letters(s, 'a', 'z', -32)
  end function upper

  !> s with every character in first..last moved by `offset` places in the ASCII table.
  pure function shift_letters(s, first, last, offset) result(t)
    character(*), intent(in) :: s
    !> The range of characters moved.
    character, intent(in) :: first, last
    !> Places moved (+32: to lower case, -32: to upper case).
    integer, intent(in) :: offset
    character(len=len(s)) :: t
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar(first) .and. c <= iachar(last)) t(i:i) = achar(c + offset)
    end do
  end function shift_letters

end module kinetostat_text
