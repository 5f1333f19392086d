!> Output policy, in one place: every number that reaches any output becomes text here.
!> A finite value too wide for its fixed-point field is printed in exponent form in that
!> field (never `*`); three-digit exponents keep their `E`; CSV and JSON numbers carry 13
!> significant digits; flags and counts are whole numbers. Non-finite values never get
!> here: the run pipeline rejects them first (see kinetostat_run).
module kinetostat_format
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: fixed_field, exp_field, int_field, full_number, whole_number, cell_number
  public :: echo_number, echo_array_number, footer_number, pad_right, display_width
  public :: fixed_number, short_number

  !> A full-precision number (CSV, JSON): 13 significant digits, 3-digit exponent.
  character(*), parameter :: full_fmt = '(es20.12e3)'
  !> A deck value in the INPUT DATA echo.
  character(*), parameter :: echo_fmt = '(es18.9)'
  !> The same for values whose decimal exponent has three digits.
  character(*), parameter :: echo_e3_fmt = '(es18.9e3)'
  !> One value of an echoed array.
  character(*), parameter :: echo_array_fmt = '(es14.6)'
  !> The same for three-digit exponents.
  character(*), parameter :: echo_array_e3_fmt = '(es14.5e3)'
  !> A self-check figure in the footer.
  character(*), parameter :: footer_fmt = '(es10.2)'
  !> The same for three-digit exponents.
  character(*), parameter :: footer_e3_fmt = '(es10.1e3)'
  !> Format of the format of fixed_number (its decimals go in): F0.d.
  character(*), parameter :: fixed_number_fmt_fmt = '("(f0.",i0,")")'
  !> A short label number beyond the fixed-point range: 3 significant digits.
  character(*), parameter :: short_exp_fmt = '(es10.2)'
  !> Width of the scratch buffer for one field.
  integer, parameter :: scratch_len = 64

contains

  !> Whether |x| needs a three-digit decimal exponent (|x| >= 1e100 or 0 < |x| < 1e-99).
  pure logical function needs_e3(x)
    real(wp), intent(in) :: x
    needs_e3 = abs(x) >= 1.0e99_wp .or. (x /= 0.0_wp .and. abs(x) < 1.0e-98_wp)
  end function needs_e3

  !> A right-justified field of `width` characters: fixed point with `decimals` decimals when
  !> that leaves at least one blank in front, otherwise exponent form with as many digits as
  !> fit (still at least one blank in front), so neighbouring fields never run together.
  pure function fixed_field(x, width, decimals) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Field width, characters (>= 9).
    integer, intent(in) :: width
    !> Decimals of the fixed-point form.
    integer, intent(in) :: decimals
    character(len=width) :: text
    character(len=scratch_len) :: buf
    character(len=16) :: fmt
    if (abs(x) < 1.0e30_wp) then
      write (fmt, '("(f",i0,".",i0,")")') scratch_len, decimals
      write (buf, fmt) x + 0.0_wp
      buf = adjustl(buf)
      if (len_trim(buf) < width) then
        text = adjustr(buf(1:width))
        return
      end if
    end if
    text = exponent_text(x, width)
  end function fixed_field

  !> Exponent form in `width` characters with one blank in front (ES, digits as fit).
  pure function exponent_text(x, width) result(text)
    real(wp), intent(in) :: x
    integer, intent(in) :: width
    character(len=width) :: text
    character(len=24) :: fmt
    integer :: digits
    if (needs_e3(x)) then
      digits = max(0, width - 9)
      write (fmt, '("(es",i0,".",i0,"e3)")') width, digits
    else
      digits = max(0, width - 8)
      write (fmt, '("(es",i0,".",i0,")")') width, digits
    end if
    write (text, fmt) x + 0.0_wp
  end function exponent_text

  !> A field in the legacy E form (`Ew.d`, e.g. 0.123E+04), with an `E` kept for
  !> three-digit exponents.
  pure function exp_field(x, width, decimals) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Field width, characters.
    integer, intent(in) :: width
    !> Significant digits after the point.
    integer, intent(in) :: decimals
    character(len=width) :: text
    character(len=24) :: fmt
    if (needs_e3(x)) then
      write (fmt, '("(e",i0,".",i0,"e3)")') width, max(0, min(decimals, width - 9))
    else
      write (fmt, '("(e",i0,".",i0,")")') width, decimals
    end if
    write (text, fmt) x + 0.0_wp
  end function exp_field

  !> A right-justified whole number in `width` characters (exponent form if it cannot fit).
  pure function int_field(x, width) result(text)
    !> Finite value (rounded to the nearest whole number).
    real(wp), intent(in) :: x
    !> Field width, characters.
    integer, intent(in) :: width
    character(len=width) :: text
    character(len=scratch_len) :: buf
    if (abs(x) < 1.0e15_wp) then
      write (buf, '(i0)') nint(x, kind=int64)
      if (len_trim(buf) <= width) then
        text = adjustr(buf(1:width))
        return
      end if
    end if
    text = exponent_text(x, max(width, 9))
  end function int_field

  !> A number at full precision without blanks (CSV cells, JSON numbers): 13 significant
  !> digits, e.g. 2.741190000000E+003; minus zero is written as zero.
  pure function full_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=scratch_len) :: buf
    write (buf, full_fmt) x + 0.0_wp
    text = trim(adjustl(buf))
  end function full_number

  !> A whole number without blanks (flags and counts); full_number when beyond 1e15.
  pure function whole_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=scratch_len) :: buf
    if (abs(x) < 1.0e15_wp .and. x == aint(x)) then
      write (buf, '(i0)') nint(x, kind=int64)
      text = trim(buf)
    else
      text = full_number(x)
    end if
  end function whole_number

  !> A CSV cell or JSON number: whole_number for flags and counts, full_number otherwise.
  pure function cell_number(x, whole) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> True for a column of whole numbers.
    logical, intent(in) :: whole
    character(len=:), allocatable :: text
    if (whole) then
      text = whole_number(x)
    else
      text = full_number(x)
    end if
  end function cell_number

  !> An INPUT DATA value (18 characters).
  pure function echo_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=18) :: text
    if (needs_e3(x)) then
      write (text, echo_e3_fmt) x + 0.0_wp
    else
      write (text, echo_fmt) x + 0.0_wp
    end if
  end function echo_number

  !> One value of an echoed array (14 characters).
  pure function echo_array_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=14) :: text
    if (needs_e3(x)) then
      write (text, echo_array_e3_fmt) x + 0.0_wp
    else
      write (text, echo_array_fmt) x + 0.0_wp
    end if
  end function echo_array_number

  !> A self-check figure in the footer (10 characters).
  pure function footer_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=10) :: text
    if (needs_e3(x)) then
      write (text, footer_e3_fmt) x + 0.0_wp
    else
      write (text, footer_fmt) x + 0.0_wp
    end if
  end function footer_number

  !> A number in fixed point with `decimals` decimals and no blanks (drawing coordinates and
  !> labels of the SVG sheets): a leading zero is always written ("0.50", "-0.25"), a value
  !> that rounds to zero is written without a sign; |x| >= 1e15 goes to exponent form.
  pure function fixed_number(x, decimals) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Decimals (0 gives a whole number without a point).
    integer, intent(in) :: decimals
    character(len=:), allocatable :: text
    character(len=scratch_len) :: buf
    character(len=16) :: fmt
    real(wp) :: scale
    if (abs(x) >= 1.0e15_wp) then
      text = full_number(x)
      return
    end if
    scale = 10.0_wp**decimals
    if (anint(abs(x) * scale) == 0.0_wp) then
      buf = "0"
      if (decimals > 0) buf = "0."//repeat("0", decimals)
      text = trim(buf)
      return
    end if
    write (fmt, fixed_number_fmt_fmt) decimals
    write (buf, fmt) x
    text = trim(adjustl(buf))
    if (text(1:1) == ".") text = "0"//text
    if (len(text) > 1) then
      if (text(1:2) == "-.") text = "-0"//text(2:)
    end if
    if (decimals == 0 .and. text(len(text):len(text)) == ".") text = text(1:len(text) - 1)
  end function fixed_number

  !> A value for a label beside a picture ("2716", "12.3", "0.457"): about three
  !> significant digits in fixed point (none after the point from 100 up), exponent form
  !> (3 significant digits) from 1e7 up.
  pure function short_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=scratch_len) :: buf
    real(wp) :: a
    a = abs(x)
    if (a >= 1.0e7_wp) then
      write (buf, short_exp_fmt) x
      text = trim(adjustl(buf))
    else if (a >= 100.0_wp) then
      text = fixed_number(x, 0)
    else if (a >= 10.0_wp) then
      text = fixed_number(x, 1)
    else if (a >= 1.0_wp) then
      text = fixed_number(x, 2)
    else if (a >= 1.0e-3_wp) then
      text = fixed_number(x, 3)
    else if (a == 0.0_wp) then
      text = "0"
    else
      write (buf, short_exp_fmt) x
      text = trim(adjustl(buf))
    end if
  end function short_number

  !> Characters a UTF-8 text takes on screen (continuation bytes 0x80-0xBF not counted), so
  !> that Cyrillic labels (two bytes a letter) keep columns aligned.
  pure integer function display_width(s)
    !> UTF-8 text.
    character(*), intent(in) :: s
    integer :: i, c
    display_width = 0
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c < 128 .or. c >= 192) display_width = display_width + 1
    end do
  end function display_width

  !> `s` followed by blanks up to `width` display characters (unchanged when wider).
  pure function pad_right(s, width) result(t)
    !> UTF-8 text.
    character(*), intent(in) :: s
    !> Display width wanted.
    integer, intent(in) :: width
    character(len=:), allocatable :: t
    t = s//repeat(" ", max(0, width - display_width(s)))
  end function pad_right

end module kinetostat_format
