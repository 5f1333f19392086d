!> Deck overrides given on the command line (`--set NAME=VALUE`, and each variant of a
!> sweep): checked for form, then written into the in-memory deck as one more assignment
!> just before the first group's closing '/'. A later namelist assignment wins, so an
!> override goes through exactly the READ and the validation of the deck itself; a name the
!> deck does not have is added the same way. Overridden values are marked in the INPUT DATA
!> echo.
module kinetostat_override
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_error, only: error_t, fatal_error, exit_input, out_of_memory
  use kinetostat_text, only: upper, is_letter, is_digit, put_piece
  use kinetostat_deck, only: deck_source_t, deck_source_from_text, deck_line_count, deck_line, deck_line_length
  use kinetostat_step_table, only: step_table_t, echo_heading_kind, echo_line_kind
  use kinetostat_deck_encoding, only: utf8_problem
  implicit none
  private
  public :: override_t, parse_override, apply_overrides, mark_overrides, first_override_line, append_override

  !> One override.
  type :: override_t
    !> Namelist designator as given, without surrounding blanks ("l_ab", "dyad(2)%l2").
    character(len=:), allocatable :: name
    !> Value in namelist syntax as given ("0.45", "'flat'", "1, 2, 3").
    character(len=:), allocatable :: value
  end type override_t

contains

  !> An override from "NAME=VALUE". NAME must be a namelist designator (letters, digits,
  !> '_', subscripts in parentheses, '%' members); VALUE must be non-empty, UTF-8, with
  !> balanced quotes and, outside quotes, no '/', '&', '$', '!' or '=' (which would end the group,
  !> start a comment or smuggle in a second assignment).
  pure subroutine parse_override(arg, option, override, error)
    !> The argument ("l_ab=0.12").
    character(*), intent(in) :: arg
    !> The option it came with, for messages ("--set", "--vary").
    character(*), intent(in) :: option
    !> The override.
    type(override_t), intent(out) :: override
    !> Input error (exit 2) naming the option and the argument.
    type(error_t), allocatable, intent(out) :: error
    integer :: eq
    character(len=:), allocatable :: what
    what = option//" '"//arg//"': "
    eq = index(arg, "=")
    if (eq == 0) then
      call fatal_error(error, exit_input, what//"expected NAME=VALUE (e.g. "//option//" l_ab=0.12)")
      return
    end if
    override%name = trim(adjustl(arg(1:eq - 1)))
    override%value = trim(adjustl(arg(eq + 1:)))
    if (.not. is_designator(override%name)) then
      call fatal_error(error, exit_input, what//"'"//override%name//"' is not a deck variable name "// &
        "(letters, digits, '_', subscripts like f5c(3), members like dyad(2)%l2)")
    else if (len(override%value) == 0) then
      call fatal_error(error, exit_input, what//"no value after '='")
    else if (len(utf8_problem(override%value)) > 0) then
      call fatal_error(error, exit_input, what//utf8_problem(override%value)//" (a deck's text is UTF-8)")
    else if (.not. is_plain_value(override%value)) then
      call fatal_error(error, exit_input, what//"the value must be one namelist value list: "// &
        "balanced quotes, and no '/', '&', '$', '!' or '=' outside quotes")
    end if
  end subroutine parse_override

  !> Whether `name` looks like a namelist designator: a letter, then letters, digits, '_',
  !> and '%' members, each part optionally subscripted with digits, ',', ':', '+', '-' and
  !> blanks in balanced, unnested parentheses.
  pure logical function is_designator(name)
    character(*), intent(in) :: name
    integer :: i
    logical :: inside, part_start
    is_designator = .false.
    if (len(name) == 0) return
    inside = .false.
    part_start = .true.
    do i = 1, len(name)
      associate (c => name(i:i))
        if (inside) then
          if (c == ")") then
            inside = .false.
          else if (.not. (is_digit(c) .or. index(",:+- ", c) > 0)) then
            return
          end if
        else if (part_start) then
          if (.not. is_letter(c)) return
          part_start = .false.
        else if (c == "(") then
          if (name(i - 1:i - 1) == ")") return
          inside = .true.
        else if (c == "%") then
          part_start = .true.
        else if (.not. (is_letter(c) .or. is_digit(c) .or. c == "_")) then
          return
        else if (name(i - 1:i - 1) == ")") then
          return
        end if
      end associate
    end do
    is_designator = .not. inside .and. .not. part_start
  end function is_designator

  !> Whether `value` is a value list that cannot end the group or add an assignment.
  pure logical function is_plain_value(value)
    character(*), intent(in) :: value
    integer :: i
    character(len=1) :: quote
    is_plain_value = .false.
    quote = " "
    do i = 1, len(value)
      associate (c => value(i:i))
        if (quote /= " ") then
          if (c == quote) quote = " "
        else if (c == "'" .or. c == '"') then
          quote = c
        else if (index("/&$!=", c) > 0 .or. iachar(c) < 32) then
          return
        end if
      end associate
    end do
    is_plain_value = quote == " "
  end function is_plain_value

  !> The deck with the overrides written, one "  NAME = VALUE" line each and in order, just
  !> before the closing '/' (or '&end') of its first namelist group; the deck's own lines
  !> keep their numbers. A deck whose first group is not closed gets them at its end (its
  !> READ then fails as the deck alone would).
  pure subroutine apply_overrides(source, overrides, patched, error)
    !> The deck as read.
    type(deck_source_t), intent(in) :: source
    !> The overrides, in command-line order.
    type(override_t), intent(in) :: overrides(:)
    !> The deck to read.
    type(deck_source_t), intent(out) :: patched
    !> The patched deck does not fit in memory (exit 2; when given: without it, the
    !> allocation's own failure ends the program).
    type(error_t), allocatable, intent(out), optional :: error
    character(*), parameter :: lf = achar(10)
    character(len=:), allocatable :: text, added, line
    integer :: k, col, i, at, size_text, stat
    added = ""
    do i = 1, size(overrides)
      added = added//"  "//overrides(i)%name//" = "//overrides(i)%value//lf
    end do
    call group_end(source, k, col)
    ! the text is built in place: the deck's lines, the added ones, a line break at `col`
    size_text = len(added) + 1
    do i = 1, deck_line_count(source)
      size_text = size_text + deck_line_length(source, i) + 1
    end do
    allocate (character(len=size_text) :: text, stat=stat)
    if (stat /= 0) then
      if (present(error)) then
        call out_of_memory(error, "the deck with its --set overrides", int(size_text, int64))
        error%message = source%path//": "//error%message
      end if
      return
    end if
    at = 0
    do i = 1, deck_line_count(source)
      line = deck_line(source, i)
      if (i == k) then
        if (col > 1) call put_piece(text, at, line(1:col - 1)//lf)
        call put_piece(text, at, added)
        call put_piece(text, at, line(col:)//lf)
      else
        call put_piece(text, at, line//lf)
      end if
    end do
    if (k == 0) call put_piece(text, at, added)
    call deck_source_from_text(source%path, text(1:at), patched, error=error)
    if (present(error)) then
      if (allocated(error)) error%message = source%path//": "//error%message
    end if
  end subroutine apply_overrides

  !> The line of the first override in the deck apply_overrides writes (override i is on
  !> the line after override i - 1): the line of the group's closing '/', or the line after
  !> it when text stands before the '/' on its line, or after the deck's last line when the
  !> group is not closed.
  pure integer function first_override_line(source) result(line)
    !> The deck as read.
    type(deck_source_t), intent(in) :: source
    integer :: k, col
    call group_end(source, k, col)
    if (k == 0) then
      line = deck_line_count(source) + 1
    else if (col > 1) then
      line = k + 1
    else
      line = k
    end if
  end function first_override_line

  !> Line `k` and column `col` of the character that closes the deck's first namelist group:
  !> the first '/', '&' or '$' after the group name outside quotes and '!' comments
  !> (0, 0 when the group is not closed).
  pure subroutine group_end(source, k, col)
    type(deck_source_t), intent(in) :: source
    integer, intent(out) :: k, col
    integer :: line, i, first
    character(len=1) :: quote
    character(len=:), allocatable :: text
    logical :: started
    k = 0
    col = 0
    started = .false.
    quote = " "
    do line = 1, deck_line_count(source)
      first = 1
      text = deck_line(source, line)
      if (.not. started) then
        first = index(text, "&")
        if (first == 0) cycle
        if (len_trim(text(1:first - 1)) > 0) cycle
        ! skip the group name
        first = first + 1
        do while (first <= len(text))
          if (index(" /,!", text(first:first)) > 0) exit
          first = first + 1
        end do
        started = .true.
      end if
      do i = first, len(text)
        associate (c => text(i:i))
          if (quote /= " ") then
            if (c == quote) quote = " "
          else if (c == "'" .or. c == '"') then
            quote = c
          else if (c == "!") then
            exit
          else if (index("/&$", c) > 0) then
            k = line
            col = i
            return
          end if
        end associate
      end do
    end do
  end subroutine group_end

  !> Mark the run as overridden: the overrides as given go first in the INPUT DATA echo
  !> (`table%overrides`), and the echo record of a plain variable or array set by --set is
  !> marked when exactly one record carries its name (a member of a derived type, or a
  !> name echoed in several blocks, is shown by the first lines only).
  pure subroutine mark_overrides(table, overrides)
    !> The run's results.
    type(step_table_t), intent(inout) :: table
    !> The overrides.
    type(override_t), intent(in) :: overrides(:)
    integer :: i, j, hits, at, paren
    character(len=:), allocatable :: base
    integer :: longest
    longest = 0
    do i = 1, size(overrides)
      longest = max(longest, len(overrides(i)%name) + 1 + len(overrides(i)%value))
    end do
    allocate (character(len=longest) :: table%overrides(size(overrides)))
    do i = 1, size(overrides)
      table%overrides(i) = overrides(i)%name//"="//overrides(i)%value
      if (index(overrides(i)%name, "%") > 0) cycle
      paren = index(overrides(i)%name, "(")
      if (paren > 0) then
        base = upper(overrides(i)%name(1:paren - 1))
      else
        base = upper(overrides(i)%name)
      end if
      hits = 0
      at = 0
      do j = 1, table%echo_count
        if (table%echo(j)%kind == echo_heading_kind .or. table%echo(j)%kind == echo_line_kind) cycle
        if (upper(table%echo(j)%name) == base) then
          hits = hits + 1
          at = j
        end if
      end do
      if (hits == 1) table%echo(at)%overridden = .true.
    end do
  end subroutine mark_overrides

  !> Append the assignment `name = value` (element by element: no array constructor of a
  !> type with deferred-length components).
  pure subroutine append_override(overrides, name, value)
    type(override_t), allocatable, intent(inout) :: overrides(:)
    character(*), intent(in) :: name, value
    type(override_t), allocatable :: grown(:)
    integer :: n, k
    n = size(overrides)
    allocate (grown(n + 1))
    ! moved, not copied
    do k = 1, n
      call move_alloc(overrides(k)%name, grown(k)%name)
      call move_alloc(overrides(k)%value, grown(k)%value)
    end do
    grown(n + 1)%name = name
    grown(n + 1)%value = value
    call move_alloc(grown, overrides)
  end subroutine append_override

end module kinetostat_override
