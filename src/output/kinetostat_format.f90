!> Output policy, in one place: every number that reaches any output becomes text here.
!> A finite value too wide for its fixed-point field is printed in exponent form in that
!> field (never `*`); three-digit exponents keep their `E`; CSV and JSON numbers carry 13
!> significant digits; flags and counts are whole numbers. Non-finite values never get
!> here: the run pipeline rejects them first (see kinetostat_run).
!> Field routines write into a character(*) dummy whose length is the field width.
! allow(assumed-size-character-intent)
module kinetostat_format
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_decimal, only: edit_f, edit_exponent, put_whole, put_cell_number
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: fixed_field, exp_field, int_field, full_number, whole_number, cell_number
  public :: echo_number, echo_array_number, footer_number, limit_number, pad_right, pad_left, display_width
  public :: put_cell, put_cells, put_fixed, cell_room, fixed_number, short_number, trimmed_es

  ! The edit descriptors of the policy (kinetostat_decimal writes them exactly as the
  ! compiler's formatted WRITE would, only faster):
  !   CSV cell, JSON number   ES20.12E3 without blanks; in a column of flags or counts a whole
  !                           value below 1e15 as I0 (kinetostat_decimal's put_cell_number,
  !                           a row at once: put_cell_numbers)
  !   INPUT DATA value        ES18.9, ES18.9E3 for three-digit exponents
  !   echoed array value      ES14.6, ES14.5E3
  !   self-check figure       ES10.2, ES10.1E3; its limit ES8.1
  !   table fields            Fw.d, else ESw.(w-8) / ESw.(w-9)E3; legacy Ew.d / Ew.dE3
  !> Room a CSV cell needs at most, characters.
  integer, parameter :: cell_room = 24
  !> Width of the scratch buffer for one field.
  integer, parameter :: scratch_len = 64
  !> Index of the implied DO loop below.
  integer, private :: i_
  !> 0.5 * 10**(-d), d = 0..18: half a unit of the last decimal of a fixed-point field (the
  !> same numbers as the expression: 10**d is exact, its reciprocal correctly rounded).
  real(wp), parameter :: half_units(0:18) = [(0.5_wp / 10.0_wp**i_, i_ = 0, 18)]

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
    call fixed_text(x, decimals, text)
  end function fixed_field

  !> fixed_field into `text` (its length is the width).
  pure subroutine fixed_text(x, decimals, text)
    real(wp), intent(in) :: x
    integer, intent(in) :: decimals
    character(*), intent(out) :: text
    logical :: fits
    real(wp) :: y
    fits = .false.
    ! a value that rounds to zero at these decimals is printed as 0.00, never -0.00
    y = x + 0.0_wp
    if (decimals >= 0 .and. decimals <= ubound(half_units, 1)) then
      if (abs(x) < half_units(decimals)) y = 0.0_wp
    else if (abs(x) < 0.5_wp * 10.0_wp**(-decimals)) then
      y = 0.0_wp
    end if
    if (abs(x) < 1.0e30_wp) call edit_f(y, decimals, text, fits)
    if (.not. fits) call exponent_text(x, text)
  end subroutine fixed_text

  !> x in ES form right-justified in `len(text)` characters: `decimals` digits after the point
  !> with a two-digit exponent, or `decimals_e3` digits and a three-digit exponent when the
  !> exponent needs three digits (see needs_e3).
  pure subroutine es_text(x, decimals, decimals_e3, text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Digits after the point with a two-digit exponent.
    integer, intent(in) :: decimals
    !> Digits after the point with a three-digit exponent.
    integer, intent(in) :: decimals_e3
    !> The field.
    character(*), intent(out) :: text
    if (needs_e3(x)) then
      call edit_exponent(x + 0.0_wp, decimals_e3, 3, scientific=.true., text=text)
    else
      call edit_exponent(x + 0.0_wp, decimals, 0, scientific=.true., text=text)
    end if
  end subroutine es_text

  !> Exponent form in `len(text)` characters with one blank in front (ES, digits as fit).
  pure subroutine exponent_text(x, text)
    real(wp), intent(in) :: x
    character(*), intent(out) :: text
    call es_text(x, max(0, len(text) - 8), max(0, len(text) - 9), text)
  end subroutine exponent_text

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
    if (needs_e3(x)) then
      call edit_exponent(x + 0.0_wp, max(0, min(decimals, width - 9)), 3, scientific=.false., text=text)
    else
      call edit_exponent(x + 0.0_wp, decimals, 0, scientific=.false., text=text)
    end if
  end function exp_field

  !> A right-justified whole number in `width` characters (exponent form if it cannot fit).
  pure function int_field(x, width) result(text)
    !> Finite value (rounded to the nearest whole number).
    real(wp), intent(in) :: x
    !> Field width, characters.
    integer, intent(in) :: width
    character(len=width) :: text
    character(len=scratch_len) :: buf
    integer :: n
    if (abs(x) < 1.0e15_wp) then
      n = 0
      call put_whole(nint(x, kind=int64), buf, n)
      if (n <= width) then
        text = repeat(" ", width - n)//buf(1:n)
        return
      end if
    end if
    if (width >= 9) then
      call exponent_text(x, text)
    else
      text = exponent_9(x)
    end if
  end function int_field

  !> exponent_text in 9 characters.
  pure function exponent_9(x) result(text)
    real(wp), intent(in) :: x
    character(len=9) :: text
    call exponent_text(x, text)
  end function exponent_9

  !> A number at full precision without blanks (CSV cells, JSON numbers): 13 significant
  !> digits, e.g. 2.741190000000E+003; minus zero is written as zero.
  pure function full_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    text = cell_number(x, .false.)
  end function full_number

  !> A whole number without blanks (flags and counts); full_number when beyond 1e15.
  pure function whole_number(x) result(text)
    !> Finite value, a whole number below 1e15 as a rule.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    text = cell_number(x, .true.)
  end function whole_number

  !> A CSV cell or JSON number: whole_number for flags and counts, full_number otherwise.
  pure function cell_number(x, whole) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> True for a column of whole numbers.
    logical, intent(in) :: whole
    character(len=:), allocatable :: text
    character(len=scratch_len) :: buf
    integer :: n
    n = 0
    call put_cell_text(x, whole, buf, n)
    text = buf(1:n)
  end function cell_number

  !> cell_number appended to buf at n+1.. (n advanced; room for 24 more).
  pure subroutine put_cell_text(x, whole, buf, n)
    real(wp), intent(in) :: x
    logical, intent(in) :: whole
    character(*), intent(inout) :: buf
    integer, intent(inout) :: n
    call put_cell_number(x, whole, buf, n)
  end subroutine put_cell_text

  !> Append cell_number(x, whole) to the output (no newline).
  pure subroutine put_cell(out, x, whole)
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    !> Finite value.
    real(wp), intent(in) :: x
    !> True for a column of whole numbers.
    logical, intent(in) :: whole
    call out%reserve(cell_room)
    call put_cell_text(x, whole, out%data, out%length)
  end subroutine put_cell

  !> Append the cells of one row (no newline): cell_number of row(columns(i)) for every i,
  !> `separator` between them, `void_text` instead of a cell with no value (void_row and
  !> voidable(i)). Room is made once for the whole row.
  pure subroutine put_cells(out, row, columns, whole, voidable, void_row, separator, void_text)
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    !> The row's values (finite where written).
    real(wp), intent(in) :: row(:)
    !> Indices into `row` of the cells, in order.
    integer, intent(in) :: columns(:)
    !> Per cell: a column of whole numbers.
    logical, intent(in) :: whole(:)
    !> Per cell: a column that has no value in a void row.
    logical, intent(in) :: voidable(:)
    !> Whether the row is void.
    logical, intent(in) :: void_row
    !> Text between two cells.
    character(*), intent(in) :: separator
    !> Text of a cell with no value.
    character(*), intent(in) :: void_text
    integer :: i, n, room
    room = size(columns) * (max(cell_room, len(void_text)) + len(separator))
    call out%reserve(room)
    n = out%length
    do i = 1, size(columns)
      if (i > 1) then
        if (len(separator) == 1) then
          out%data(n + 1:n + 1) = separator(1:1)   ! (a one-character store, not a copy call)
        else
          out%data(n + 1:n + len(separator)) = separator
        end if
        n = n + len(separator)
      end if
      if (void_row) then
        if (voidable(i)) then
          out%data(n + 1:n + len(void_text)) = void_text
          n = n + len(void_text)
          cycle
        end if
      end if
      call put_cell_text(row(columns(i)), whole(i), out%data, n)
    end do
    out%length = n
  end subroutine put_cells

  !> Append fixed_field(x, width, decimals) to the output (no newline).
  pure subroutine put_fixed(out, x, width, decimals)
    !> Where the text goes.
    type(text_buffer_t), intent(inout) :: out
    !> Finite value.
    real(wp), intent(in) :: x
    !> Field width (>= 9) and decimals, as fixed_field's.
    integer, intent(in) :: width, decimals
    call out%reserve(width)
    call fixed_text(x, decimals, out%data(out%length + 1:out%length + width))
    out%length = out%length + width
  end subroutine put_fixed

  !> An INPUT DATA value (18 characters).
  pure function echo_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=18) :: text
    call es_text(x, 9, 9, text)
  end function echo_number

  !> One value of an echoed array (14 characters).
  pure function echo_array_number(x) result(text)
    !> Finite value of the array.
    real(wp), intent(in) :: x
    character(len=14) :: text
    call es_text(x, 6, 5, text)
  end function echo_array_number

  !> A self-check figure in the footer (10 characters).
  pure function footer_number(x) result(text)
    !> Finite self-check figure.
    real(wp), intent(in) :: x
    character(len=10) :: text
    call es_text(x, 2, 1, text)
  end function footer_number

  !> A self-check limit in the footer heading, without blanks (ES8.1, e.g. 1.0E-09).
  pure function limit_number(x) result(text)
    !> Finite limit, positive as a rule.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    text = trimmed_es(x, 1)
  end function limit_number
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
    real(wp) :: scale
    logical :: fits
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
    call edit_f(x, decimals, buf, fits)   ! F0.d with its leading zero
    text = trim(adjustl(buf))
    if (decimals == 0 .and. text(len(text):len(text)) == ".") text = text(1:len(text) - 1)
  end function fixed_number

  !> A value for a label beside a picture ("2716", "12.3", "0.457"): about three
  !> significant digits in fixed point (none after the point from 100 up), exponent form
  !> (3 significant digits, ES10.2) from 1e7 up.
  pure function short_number(x) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    real(wp) :: a
    a = abs(x)
    if (a >= 1.0e7_wp) then
      text = trimmed_es(x, 2)
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
      text = trimmed_es(x, 2)
    end if
  end function short_number

  !> ES(2d+6).d without blanks: ES8.1 (1.0E-09), ES10.2 (2.50E+03); a three-digit exponent
  !> keeps its E (1.00E-300, where ESw.d alone would write 1.00-300).
  pure function trimmed_es(x, d) result(text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Digits after the point.
    integer, intent(in) :: d
    character(len=:), allocatable :: text
    character(len=2 * d + 8) :: field
    call edit_exponent(x, d, 0, scientific=.true., text=field)
    if (scan(field, "E") == 0) call edit_exponent(x, d, 3, scientific=.true., text=field)
    text = trim(adjustl(field))
  end function trimmed_es

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

  !> `text` right-justified in `width` display characters (see display_width).
  pure function pad_left(text, width) result(field)
    !> UTF-8 text.
    character(*), intent(in) :: text
    !> Display characters of the field.
    integer, intent(in) :: width
    character(len=:), allocatable :: field
    field = repeat(" ", max(0, width - display_width(text)))//text
  end function pad_left

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
