!> Small string helpers: numbers to trimmed text, lower case.
module kinetostat_text
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: real_str, int_str, int64_str, number_str, lower, upper, printable, utf8_length, char_count, counted, &
    clipped, starts_with, is_name, without_blanks, replace_all, is_letter, is_digit, put_piece, joined
  public :: string_t, trimmed, next_item

  !> One text of a list whose texts differ in length.
  type :: string_t
    !> The text.
    character(len=:), allocatable :: s
  end type string_t

  !> Texts joined by a separator ("a, b, c"): of a list of string_t, or of blank-padded names
  !> (each without its trailing blanks).
  interface joined
    module procedure joined_strings, joined_names
  end interface joined

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

  !> At most `width` characters of a text, ending in "..." when cut.
  pure function clipped(text, width) result(short)
    !> Any text.
    character(*), intent(in) :: text
    !> The most characters kept (> 3).
    integer, intent(in) :: width
    character(len=:), allocatable :: short
    short = text
    if (len(text) > width) short = text(1:width - 3)//"..."
  end function clipped

  !> Whether `text` starts with `prefix`.
  pure logical function starts_with(text, prefix)
    !> Any text.
    character(*), intent(in) :: text
    !> The start looked for.
    character(*), intent(in) :: prefix
    starts_with = .false.
    if (len(text) >= len(prefix)) starts_with = text(1:len(prefix)) == prefix
  end function starts_with

  !> A count with its noun: "1 step", "3 steps".
  pure function counted(n, noun) result(text)
    !> How many.
    integer, intent(in) :: n
    !> The noun, singular.
    character(*), intent(in) :: noun
    character(len=:), allocatable :: text
    text = int_str(n)//" "//noun
    if (n /= 1) text = text//"s"
  end function counted

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

  !> A 64-bit integer as trimmed text.
  pure function int64_str(i) result(s)
    !> Value.
    integer(int64), intent(in) :: i
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function int64_str

  !> Text made safe for a one-line message or a JSON string: valid UTF-8 is kept, a control
  !> character becomes \n, \r, \t or \xNN, and a byte that is not part of valid UTF-8
  !> (CP1251, Latin-1, 0xFF) becomes \xNN, so a message stays one line of valid UTF-8.
  pure function printable(text) result(safe)
    !> Any bytes.
    character(*), intent(in) :: text
    character(len=:), allocatable :: safe
    integer :: i, n, at
    if (verify(text, " !""#$%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\]^_`"// &
        "abcdefghijklmnopqrstuvwxyz{|}~") == 0) then
      safe = text
      return
    end if
    allocate (character(len=4 * len(text)) :: safe)
    at = 0
    i = 1
    do while (i <= len(text))
      ! a valid multi-byte character as it is, any other byte by printable_byte
      n = max(1, utf8_length(text, i))
      if (n > 1) then
        call put_piece(safe, at, text(i:i + n - 1))
      else
        call put_piece(safe, at, printable_byte(text(i:i)))
      end if
      i = i + n
    end do
    safe = safe(1:at)
  end function printable

  !> One byte as `printable` shows it: \n, \r, \t, \xNN for a control character or a byte
  !> beyond ASCII, itself otherwise.
  pure function printable_byte(byte) result(shown)
    !> The byte.
    character, intent(in) :: byte
    character(len=:), allocatable :: shown
    character(len=*), parameter :: hex = "0123456789ABCDEF"
    integer :: c
    c = iachar(byte)
    select case (c)
    case (10)
      shown = "\n"
    case (13)
      shown = "\r"
    case (9)
      shown = "\t"
    case (0:8, 11:12, 14:31, 127:255)
      shown = "\x"//hex(c / 16 + 1:c / 16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
    case default
      shown = byte
    end select
  end function printable_byte

  !> Bytes of the valid UTF-8 character at `text(i:)` (1 for ASCII, 2 to 4 for a multi-byte
  !> sequence), 0 when the byte at `i` does not start a valid one (a CP1251 or Latin-1
  !> byte, a stray continuation byte, a sequence cut short, an overlong form, a UTF-16
  !> surrogate or a code point beyond U+10FFFF: what a strict decoder refuses).
  pure integer function utf8_length(text, i) result(n)
    !> Any bytes.
    character(*), intent(in) :: text
    !> Position looked at.
    integer, intent(in) :: i
    integer :: c, k, low, high
    c = iachar(text(i:i))
    ! the range of the second byte (the others: 128..191)
    low = 128
    high = 191
    if (c < 128) then
      n = 1
      return
    else if (c >= 194 .and. c <= 223) then
      n = 2
    else if (c >= 224 .and. c <= 239) then
      n = 3
      if (c == 224) low = 160
      if (c == 237) high = 159
    else if (c >= 240 .and. c <= 244) then
      n = 4
      if (c == 240) low = 144
      if (c == 244) high = 143
    else
      n = 0
      return
    end if
    if (i + n - 1 > len(text)) then
      n = 0
      return
    end if
    if (iachar(text(i + 1:i + 1)) < low .or. iachar(text(i + 1:i + 1)) > high) then
      n = 0
      return
    end if
    do k = 2, n - 1
      if (iachar(text(i + k:i + k)) < 128 .or. iachar(text(i + k:i + k)) > 191) then
        n = 0
        return
      end if
    end do
  end function utf8_length

  !> The text without blanks and tabs (a namelist designator as the READ compares it:
  !> "dyad (1) % l2" is "dyad(1)%l2").
  pure function without_blanks(text) result(t)
    character(*), intent(in) :: text
    character(len=:), allocatable :: t
    t = replace_all(text, " ", "")
    t = replace_all(t, achar(9), "")
  end function without_blanks

  !> Characters of a text: its UTF-8 characters, each byte that is not part of one counted
  !> as one (so a Cyrillic letter counts once, not as its two bytes).
  pure integer function char_count(text)
    !> Any bytes.
    character(*), intent(in) :: text
    integer :: i
    char_count = 0
    i = 1
    do while (i <= len(text))
      i = i + max(1, utf8_length(text, i))
      char_count = char_count + 1
    end do
  end function char_count

  !> Whether `text` is a name: a letter, then letters, digits and '_'; a letter is Latin
  !> (A-Z, a-z) or Cyrillic (U+0400..U+04FF, two bytes in UTF-8: А..я, Ё, ё and the rest of
  !> the block).
  pure logical function is_name(text)
    !> Any bytes (no trailing blanks).
    character(*), intent(in) :: text
    integer :: i, c
    logical :: letter
    is_name = .false.
    if (len(text) == 0) return
    i = 1
    do while (i <= len(text))
      c = iachar(text(i:i))
      letter = (c >= iachar("A") .and. c <= iachar("Z")) .or. (c >= iachar("a") .and. c <= iachar("z"))
      if (c >= 208 .and. c <= 211 .and. i < len(text)) then
        if (iachar(text(i + 1:i + 1)) >= 128 .and. iachar(text(i + 1:i + 1)) <= 191) then
          i = i + 2
          cycle
        end if
      end if
      if (.not. letter .and. (i == 1 .or. .not. (c == iachar("_") .or. (c >= iachar("0") .and. c <= iachar("9"))))) return
      i = i + 1
    end do
    is_name = .true.
  end function is_name

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

  !> `text` with every `old` replaced by `new`.
  pure recursive function replace_all(text, old, new) result(out)
    character(*), intent(in) :: text, old, new
    character(len=:), allocatable :: out
    integer :: i
    i = index(text, old)
    if (i == 0) then
      out = text
    else
      out = text(:i - 1)//new//replace_all(text(i + len(old):), old, new)
    end if
  end function replace_all

  !> Whether `c` is an ASCII letter (A-Z, a-z).
  pure logical function is_letter(c)
    character, intent(in) :: c
    is_letter = (c >= "A" .and. c <= "Z") .or. (c >= "a" .and. c <= "z")
  end function is_letter

  !> Whether `c` is an ASCII digit.
  pure logical function is_digit(c)
    character, intent(in) :: c
    is_digit = c >= "0" .and. c <= "9"
  end function is_digit

  !> Append `piece` to `text` after its first `at` characters (`text` allocated long enough).
  pure subroutine put_piece(text, at, piece)
    !> The text being built.
    character(len=:), allocatable, intent(inout) :: text
    !> Characters of it used so far; moved past the piece.
    integer, intent(inout) :: at
    !> What is added.
    character(*), intent(in) :: piece
    text(at + 1:at + len(piece)) = piece
    at = at + len(piece)
  end subroutine put_piece

  !> The texts of `parts` one after the other, `separator` between two.
  pure function joined_strings(parts, separator) result(text)
    type(string_t), intent(in) :: parts(:)
    character(*), intent(in) :: separator
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, size(parts)
      if (i > 1) text = text//separator
      text = text//parts(i)%s
    end do
  end function joined_strings

  !> The names without their trailing blanks one after the other, `separator` between two.
  pure function joined_names(names, separator) result(text)
    character(*), intent(in) :: names(:)
    character(*), intent(in) :: separator
    character(len=:), allocatable :: text
    text = joined_strings(trimmed(names), separator)
  end function joined_names

  !> The item of a comma-separated list that starts at `start`, without the blanks around
  !> it; `start` moves past the item's comma, to 0 after the last item. Walk a list with
  !>     start = 1
  !>     do while (start > 0)
  !>       call next_item(list, start, item)
  pure subroutine next_item(list, start, item)
    !> The list ("F12, F23").
    character(*), intent(in) :: list
    !> Where the item starts (1 for the first); then where the next one does, or 0.
    integer, intent(inout) :: start
    !> The item.
    character(len=:), allocatable, intent(out) :: item
    integer :: comma
    comma = index(list(start:), ",")
    if (comma == 0) then
      item = trim(adjustl(list(start:)))
      start = 0
    else
      item = trim(adjustl(list(start:start + comma - 2)))
      start = start + comma
    end if
  end subroutine next_item

  !> A blank-padded name as a string_t, without its trailing blanks.
  elemental function trimmed(name) result(part)
    character(*), intent(in) :: name
    type(string_t) :: part
    part%s = trim(name)
  end function trimmed

end module kinetostat_text
