!> The escapers of the output formats: every text a user supplied (deck path, title, student
!> fields, joint and link names, --set text) reaches an output only through one of these,
!> applied where the format's text is emitted (the JSON string, the SVG text and attribute,
!> the CSV field, the DXF TEXT value, the legacy table's line, the npy header's field name). Whatever the bytes, the output
!> stays valid: one physical line per CSV row and table line, well-formed XML, parseable JSON,
!> DXF group-code pairs in ASCII. A control character is shown as messages show it (\n, \r,
!> \t, \xNN) and so is a byte that is not part of valid UTF-8 (\xNN); JSON writes these as
!> its own escapes (\n, \u00NN). docs/cli.md, "Strings in outputs".
module kinetostat_escape
  use kinetostat_text, only: printable, utf8_length, replace_all, put_piece
  implicit none
  private
  public :: json_string, xml_escape, csv_field, dxf_text, table_text, python_string, namelist_string

  character(*), parameter :: hex_digits = "0123456789ABCDEF"

contains

  !> A JSON string literal, with its quotes: `"` and `\` escaped, newline, carriage return and
  !> tab as \n, \r, \t, any other control character and any byte that is not part of valid
  !> UTF-8 as \u00NN (the byte as its Latin-1 character: the file stays valid UTF-8 and
  !> valid JSON); valid UTF-8 kept.
  pure function json_string(s) result(text)
    !> Any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: text
    text = quoted_literal(s, '"', "\u00")
  end function json_string

  !> A Python string literal in single quotes, as the header of an npy file holds a field's
  !> name (numpy reads it with Python's literal parser): `'` and `\` escaped, newline, carriage
  !> return and tab as \n, \r, \t, any other control character and any byte that is not part
  !> of valid UTF-8 as \xNN (the byte as its Latin-1 character); valid UTF-8 kept.
  pure function python_string(s) result(text)
    !> A field's name: any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: text
    text = quoted_literal(s, "'", "\x")
  end function python_string

  !> A Fortran namelist string literal in single quotes, as a deck written by the program
  !> holds a title or a name (`kinetostat convert`): a quote doubled. The texts it gets were
  !> read from a deck, so they hold no line break.
  pure function namelist_string(s) result(text)
    !> A text read from a deck.
    character(*), intent(in) :: s
    character(len=:), allocatable :: text
    text = "'"//replace_all(s, "'", "''")//"'"
  end function namelist_string

  !> A string literal between `quote`s as JSON and Python write one: the quote and `\` escaped,
  !> newline, carriage return and tab as \n, \r, \t, any other control character and any byte
  !> that is not part of valid UTF-8 as `byte_escape` and the byte's two hex digits; valid UTF-8
  !> kept.
  pure function quoted_literal(s, quote, byte_escape) result(text)
    !> Any bytes.
    character(*), intent(in) :: s
    !> The quote character.
    character, intent(in) :: quote
    !> What stands before a byte's hex digits: "\u00" (JSON) or "\x" (Python).
    character(*), intent(in) :: byte_escape
    character(len=:), allocatable :: text
    integer :: i, c, n, at
    allocate (character(len=(len(byte_escape) + 2) * len(s) + 2) :: text)
    text(1:1) = quote
    at = 1
    i = 1
    do while (i <= len(s))
      c = iachar(s(i:i))
      n = utf8_length(s, i)
      if (s(i:i) == quote .or. s(i:i) == '\') then
        call put_piece(text, at, '\'//s(i:i))
      else if (c == 10) then
        call put_piece(text, at, "\n")
      else if (c == 13) then
        call put_piece(text, at, "\r")
      else if (c == 9) then
        call put_piece(text, at, "\t")
      else if (c < 32 .or. c == 127 .or. n == 0) then
        call put_piece(text, at, byte_escape//hex_byte(c))
      else
        call put_piece(text, at, s(i:i + n - 1))
        i = i + n
        cycle
      end if
      i = i + 1
    end do
    call put_piece(text, at, quote)
    text = text(1:at)
  end function quoted_literal

  !> Text for an XML (SVG) text node or attribute value: shown as messages show it (a control
  !> character or a byte that is not valid UTF-8 as the visible \n, \t, \xNN), then the five
  !> special characters as entities (&amp; &lt; &gt; &quot; &apos;), so "]]>" is "]]&gt;".
  pure function xml_escape(s) result(t)
    !> Any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: t
    character(len=:), allocatable :: shown
    integer :: i, at
    shown = printable(s)
    if (scan(shown, "&<>""'"//char(239)) == 0) then
      t = shown
      return
    end if
    ! U+FFFE and U+FFFF are valid UTF-8 but no XML character: shown as their bytes
    do
      i = index(shown, char(239)//char(191)//char(190))
      if (i == 0) i = index(shown, char(239)//char(191)//char(191))
      if (i == 0) exit
      shown = shown(:i - 1)//"\xEF\xBF\x"//hex_byte(iachar(shown(i + 2:i + 2)))//shown(i + 3:)
    end do
    allocate (character(len=6 * len(shown)) :: t)
    at = 0
    do i = 1, len(shown)
      select case (shown(i:i))
      case ("&")
        call put_piece(t, at, "&amp;")
      case ("<")
        call put_piece(t, at, "&lt;")
      case (">")
        call put_piece(t, at, "&gt;")
      case ('"')
        call put_piece(t, at, "&quot;")
      case ("'")
        call put_piece(t, at, "&apos;")
      case default
        call put_piece(t, at, shown(i:i))
      end select
    end do
    t = t(1:at)
  end function xml_escape

  !> A CSV field (RFC 4180) that stays on its row's line: shown as messages show it (control
  !> characters and bytes that are not valid UTF-8 as \n, \t, \xNN), then in double quotes,
  !> with its quotes doubled, when it holds a comma, a quote or a blank.
  pure function csv_field(s) result(t)
    !> Any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: t
    character(len=:), allocatable :: shown
    shown = printable(s)
    if (scan(shown, ', "') == 0) then
      t = shown
      return
    end if
    t = '"'//replace_all(shown, '"', '""')//'"'
  end function csv_field

  !> The value of a DXF TEXT entity (group code 1) in an R12 file, which is ASCII: a character
  !> beyond ASCII as \U+XXXX (its Unicode code point; beyond U+FFFF as the two UTF-16
  !> surrogates), which AutoCAD, LibreCAD and ezdxf read; a control character or a byte that
  !> is not valid UTF-8 as \n, \t, \xNN (so a value is one line and never a group code of
  !> its own); a caret as "^ " (a caret before a character is a control character in DXF); in
  !> a text holding "%%" (AutoCAD's special characters, %%d for the degree sign) every "%" as
  !> "%%%".
  pure function dxf_text(s) result(t)
    !> Any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: t
    integer :: i, c, n, at, code
    logical :: percents
    if (verify(s, " !""#$%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\]_`"// &
        "abcdefghijklmnopqrstuvwxyz{|}~") == 0 .and. index(s, "%%") == 0) then
      t = s
      return
    end if
    percents = index(s, "%%") > 0
    allocate (character(len=14 * len(s)) :: t)
    at = 0
    i = 1
    do while (i <= len(s))
      c = iachar(s(i:i))
      n = utf8_length(s, i)
      if (n > 1) then
        code = code_point(s(i:i + n - 1))
        if (code > 65535) then
          call put_piece(t, at, "\U+"//hex4(55296 + (code - 65536) / 1024)//"\U+"//hex4(56320 + mod(code - 65536, 1024)))
        else
          call put_piece(t, at, "\U+"//hex4(code))
        end if
        i = i + n
        cycle
      end if
      if (s(i:i) == "^") then
        call put_piece(t, at, "^ ")
      else if (s(i:i) == "%" .and. percents) then
        call put_piece(t, at, "%%%")
      else if (c < 32 .or. c >= 127) then
        call put_piece(t, at, printable(s(i:i)))
      else
        call put_piece(t, at, s(i:i))
      end if
      i = i + 1
    end do
    t = t(1:at)
  end function dxf_text

  !> Text for a line of the legacy table (or any plain-text report): one line of valid UTF-8
  !> without control characters, shown as messages show it (\n, \t, \xNN).
  pure function table_text(s) result(t)
    !> Any bytes.
    character(*), intent(in) :: s
    character(len=:), allocatable :: t
    t = printable(s)
  end function table_text

  !> The Unicode code point of one valid multi-byte UTF-8 character.
  pure integer function code_point(u)
    !> Its 2 to 4 bytes.
    character(*), intent(in) :: u
    integer :: k
    select case (len(u))
    case (2)
      code_point = iand(iachar(u(1:1)), 31)
    case (3)
      code_point = iand(iachar(u(1:1)), 15)
    case default
      code_point = iand(iachar(u(1:1)), 7)
    end select
    do k = 2, len(u)
      code_point = code_point * 64 + iand(iachar(u(k:k)), 63)
    end do
  end function code_point

  !> A byte as two upper-case hex digits.
  pure function hex_byte(c) result(t)
    integer, intent(in) :: c
    character(len=2) :: t
    t = hex_digits(c / 16 + 1:c / 16 + 1)//hex_digits(mod(c, 16) + 1:mod(c, 16) + 1)
  end function hex_byte

  !> A number 0..65535 as four upper-case hex digits.
  pure function hex4(v) result(t)
    integer, intent(in) :: v
    character(len=4) :: t
    t = hex_byte(v / 256)//hex_byte(mod(v, 256))
  end function hex4

end module kinetostat_escape
