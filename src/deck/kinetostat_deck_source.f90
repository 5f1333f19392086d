!> Loading a deck: the file (or standard input, a pipe, a device) read once into memory,
!> within the size limit, as the records of an internal file ready for a namelist READ, and
!> the deck's lines as the messages name them (the records of a very long line cut after
!> value separators, see `cut_line`).
module kinetostat_deck_source
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_error, only: error_t, fatal_error, exit_input, out_of_memory
  use kinetostat_text, only: int64_str, printable
  use kinetostat_deck_reader, only: read_bytes_limited, read_ok, read_too_long, read_no_memory
  use kinetostat_deck_encoding, only: deck_as_utf8
  implicit none
  private
  public :: deck_context_t, deck_source_t, load_deck, deck_source_from_text, stdin_deck_path, stdin_deck_name
  public :: deck_line_count, deck_line, deck_line_length, release_deck_text, line_slice, line_search
  public :: line_records, record_part, record_text, cut_line, append_length, record_width
  public :: max_deck_size, set_max_deck_size, default_max_deck_size

  !> The deck path that means standard input.
  character(*), parameter :: stdin_deck_path = "-"
  !> Name of a deck read from standard input, in messages and in the table's DECK line.
  character(*), parameter :: stdin_deck_name = "<stdin>"
  !> Default of the largest deck read, bytes (256 MiB; --max-deck-size).
  integer(int64), parameter :: default_max_deck_size = 268435456_int64
  !> Largest deck read, bytes: a longer file, or standard input or a device that gives
  !> more, is an input error (set with `set_max_deck_size`).

  integer(int64), protected :: max_deck_size = default_max_deck_size

  !> A deck read into memory: its text as the records of an internal file, ready for a
  !> namelist READ, and which line of the deck each record belongs to.
  !> A record is a line of the deck, except that a line much longer than the others (10^6
  !> per-step values on one line) is cut into several records after value separators (see
  !> `cut_line`), so the records, blank-padded to the longest, do not multiply the longest
  !> line by the number of lines. The end of a record separates values like a blank, so the
  !> READ is the same; messages name the deck's lines (`deck_line`, `deck_line_count`).
  type :: deck_source_t
    !> Name of the deck in messages (the file path as given, or e.g. "<stdin>").
    character(len=:), allocatable :: path
    !> The records: the deck's lines (or pieces of them) without line terminators (LF, CRLF)
    !> and without a leading UTF-8 byte-order mark, blank-padded to the longest record
    !> (length at least 1).
    character(len=:), allocatable :: records(:)
    !> Records of line k: first_record(k) to first_record(k + 1) - 1 (one at least; size:
    !> the number of lines + 1).
    integer, allocatable :: first_record(:)
    !> Characters of its line that each record holds (the rest is blank padding).
    integer, allocatable :: record_length(:)
    !> Lines longer than this many characters were cut (huge(1): no line was cut).
    integer :: cut_width = huge(1)
  end type deck_source_t

  !> Where a deck value comes from: file and namelist group (for messages).
  type :: deck_context_t
    !> Deck file path as given on the command line.
    character(len=:), allocatable :: path
    !> Namelist group name, lower case, without '&'.
    character(len=:), allocatable :: group
  end type deck_context_t

contains

  !> Read a whole deck file into memory (any line length, LF or CRLF line ends, with or
  !> without a final newline, optional UTF-8 byte-order mark). The path "-" reads standard
  !> input to its end (the deck is then named "<stdin>"); a pipe given as a path
  !> (/dev/stdin, /dev/fd/N, a FIFO) is read to its end as well: read once, never rewound.
  subroutine load_deck(path, source, error, whole_lines)
    !> Deck file, or "-" for standard input.
    character(*), intent(in) :: path
    !> The deck's records.
    type(deck_source_t), intent(out) :: source
    !> Set when the file cannot be opened or read, or is longer than `max_deck_size`.
    type(error_t), allocatable, intent(out) :: error
    !> One record per line, however long (for a file read as lines, not as a namelist).
    logical, intent(in), optional :: whole_lines
    integer :: cut_width
    character(len=:), allocatable :: text, name
    integer :: unit, ios, status
    integer(int64) :: file_size
    character(len=512) :: msg
    cut_width = -1
    if (present(whole_lines)) then
      if (whole_lines) cut_width = huge(1)
    end if
    if (path == stdin_deck_path) then
      call read_bytes_limited("", max_deck_size, text, status)
      call check_read(stdin_deck_name, "cannot read the deck from standard input")
      if (allocated(error)) return
      call as_utf8(stdin_deck_name)
      if (allocated(error)) return
      call deck_source_from_text(stdin_deck_name, text, source, cut_width, error)
      if (allocated(error)) error%message = stdin_deck_name//": "//error%message
      return
    end if
    name = printable(path)
    open (newunit=unit, file=path, status='old', action='read', access='stream', form='unformatted', &
          iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fatal_error(error, exit_input, name//": cannot open deck: "//printable(trim(msg)))
      return
    end if
    inquire (unit=unit, size=file_size)
    if (file_size > max_deck_size) then
      close (unit)
      call fatal_error(error, exit_input, name//": the deck is "//int64_str(file_size)// &
        " bytes, more than the limit of "//int64_str(max_deck_size)//" bytes (raise it with --max-deck-size)")
      return
    else if (file_size > 0) then
      allocate (character(len=file_size) :: text, stat=status)
      if (status /= 0) then
        close (unit)
        call out_of_memory(error, "the deck's text", file_size)
        error%message = name//": "//error%message
        return
      end if
      read (unit, iostat=ios, iomsg=msg) text
      close (unit)
      if (ios /= 0) then
        call fatal_error(error, exit_input, name//": cannot read deck: "//printable(trim(msg)))
        return
      end if
    else
      ! size unknown (pipe, device) or reported as 0: read in chunks to its end or the limit
      ! (the unit stays open meanwhile, so that a FIFO's writer still has a reader)
      call read_bytes_limited(path, max_deck_size, text, status)
      close (unit)
      call check_read(name, "cannot read deck")
      if (allocated(error)) return
    end if
    call as_utf8(name)
    if (allocated(error)) return
    call deck_source_from_text(path, text, source, cut_width, error)
    if (allocated(error)) error%message = name//": "//error%message
  contains
    !> The text as UTF-8 (a CP1251 deck decoded), or the error naming the byte at fault.
    subroutine as_utf8(deck_name)
      character(*), intent(in) :: deck_name
      character(len=:), allocatable :: problem
      if (.not. allocated(text)) return
      call deck_as_utf8(text, problem)
      if (len(problem) > 0) call fatal_error(error, exit_input, deck_name//":"//problem)
    end subroutine as_utf8
    !> The error of a read in chunks (none when all was read).
    subroutine check_read(deck_name, failure)
      character(*), intent(in) :: deck_name, failure
      select case (status)
      case (read_ok)
        continue
      case (read_too_long)
        call fatal_error(error, exit_input, deck_name//": the deck is longer than the limit of "// &
          int64_str(max_deck_size)//" bytes (endless input? raise the limit with --max-deck-size)")
      case (read_no_memory)
        call fatal_error(error, exit_input, deck_name//": out of memory: no room for the deck's text (more than "// &
          int64_str(int(len(text), int64))//" bytes read)")
      case default
        call fatal_error(error, exit_input, deck_name//": "//failure)
      end select
    end subroutine check_read
  end subroutine load_deck

  !> Set the largest deck read (bytes, 0 to huge(1): a deck's positions are default integers).
  subroutine set_max_deck_size(bytes)
    !> The limit, bytes.
    integer(int64), intent(in) :: bytes
    max_deck_size = max(0_int64, min(bytes, int(huge(1), int64)))
  end subroutine set_max_deck_size

  !> A deck from text held in memory: lines split at LF, a CR before each LF dropped, a
  !> leading UTF-8 byte-order mark dropped; a last line without LF is kept (the text is
  !> UTF-8: load_deck decodes a CP1251 deck and refuses other bytes). A line is one
  !> record, unless cutting long lines into records (see `cut_line`) at the width that
  !> needs the least memory (see `chosen_cut_width`) saves 1 MiB or more.
  pure subroutine deck_source_from_text(name, text, source, cut_width, error)
    !> Name of the deck in messages.
    character(*), intent(in) :: name
    !> The deck's text.
    character(*), intent(in) :: text
    !> The deck's records.
    type(deck_source_t), intent(out) :: source
    !> Cut the lines longer than this (characters; huge(1): none; default or < 1: chosen
    !> as above).
    integer, intent(in), optional :: cut_width
    !> The records do not fit in memory ("out of memory: ...", exit 2); when not given, the
    !> allocation's own failure ends the program.
    type(error_t), allocatable, intent(out), optional :: error
    character(len=*), parameter :: bom = char(239)//char(187)//char(191)
    integer :: first
    first = 1
    if (len(text) >= 3) then
      if (text(1:3) == bom) first = 4
    end if
    source%path = name
    call records_from_text(text(first:), source, cut_width, error)
  end subroutine deck_source_from_text

  !> The records of `text` (see deck_source_from_text; no byte-order mark handling).
  pure subroutine records_from_text(text, source, cut_width, error)
    !> The deck's text.
    character(*), intent(in) :: text
    !> The deck (its `path` is left as it is).
    type(deck_source_t), intent(inout) :: source
    !> Cut the lines longer than this (characters; huge(1): none; default or < 1: chosen).
    integer, intent(in), optional :: cut_width
    !> The records do not fit in memory (when given; without it, the allocation's own
    !> failure ends the program).
    type(error_t), allocatable, intent(out), optional :: error
    character(len=*), parameter :: lf = achar(10), cr = achar(13)
    !> Saving in bytes below which no line is cut (when the width is chosen).
    integer(int64), parameter :: least_saving = 1048576
    integer, allocatable :: line_start(:), line_end(:), lengths(:)
    integer :: stat
    integer :: n_lines, longest, i, k, s, n_records, width, depth, r, at, group_line, fixed
    character(len=1) :: quote
    ! where the lines are
    n_lines = 0
    s = 1
    do while (s <= len(text))
      call next_line(s, k, i)
      n_lines = n_lines + 1
      s = i
    end do
    allocate (line_start(n_lines), stat=stat)
    if (stat == 0) allocate (line_end(n_lines), stat=stat)
    if (stat /= 0) then
      if (present(error)) call out_of_memory(error, "the deck's line table", 8_int64 * n_lines)
      return
    end if
    s = 1
    do k = 1, n_lines
      line_start(k) = s
      call next_line(line_start(k), line_end(k), s)
    end do
    longest = 1
    if (n_lines > 0) longest = max(1, maxval(line_end - line_start + 1))
    ! the first line opening a group: where the namelist READ starts to read values; the
    ! longest line before it that is not a comment (not cut)
    group_line = n_lines + 1
    fixed = 0
    do k = 1, n_lines
      at = verify(text(line_start(k):line_end(k)), " ")
      if (at == 0) cycle
      if (text(line_start(k) + at - 1:line_start(k) + at - 1) == "&") then
        group_line = k
        exit
      end if
      if (text(line_start(k) + at - 1:line_start(k) + at - 1) /= "!") fixed = max(fixed, line_end(k) - line_start(k) + 1)
    end do
    width = -1
    if (present(cut_width)) width = cut_width
    if (width < 1) width = chosen_cut_width(line_end - line_start + 1, fixed)
    n_records = 0
    if (width < longest) then
      ! cut the long lines; the quote and parenthesis state carries from line to line
      allocate (source%first_record(n_lines + 1))
      allocate (lengths(n_lines + 64))
      quote = " "
      depth = 0
      do k = 1, n_lines
        source%first_record(k) = n_records + 1
        call cut_line(text(line_start(k):line_end(k)), width, k >= group_line, quote, depth, lengths, n_records)
      end do
      source%first_record(n_lines + 1) = n_records + 1
      ! a chosen width: cut only when it saves least_saving or more
      if (.not. present(cut_width)) then
        if (int(n_records, int64) * record_width(lengths(1:n_records)) + least_saving > int(n_lines, int64) * longest) then
          width = huge(1)
        end if
      end if
    end if
    if (width >= longest) then
      ! one record per line
      if (allocated(source%first_record)) deallocate (source%first_record)
      call allocate_records(source%records, longest, n_lines, "the deck's lines", stat, error)
      if (stat /= 0) return
      do k = 1, n_lines
        source%records(k) = text(line_start(k):line_end(k))
      end do
      source%cut_width = huge(1)
      return
    end if
    source%cut_width = width
    source%record_length = lengths(1:n_records)
    deallocate (lengths)
    width = record_width(source%record_length)
    call allocate_records(source%records, width, n_records, "the deck's records", stat, error)
    if (stat /= 0) return
    do k = 1, n_lines
      at = line_start(k)
      do r = source%first_record(k), source%first_record(k + 1) - 1
        source%records(r) = record_text(text(at:), source%record_length(r))
        at = at + abs(source%record_length(r))
      end do
    end do
  contains
    !> The line starting at `s`: its last character `e` (without LF or CR LF) and the start
    !> `following` of the next line.
    pure subroutine next_line(s, e, following)
      integer, intent(in) :: s
      integer, intent(out) :: e, following
      integer :: at
      at = index(text(s:), lf)
      if (at == 0) then
        e = len(text)
        following = len(text) + 1
      else
        e = s + at - 2
        following = s + at
      end if
      if (e >= s) then
        if (text(e:e) == cr) e = e - 1
      end if
    end subroutine next_line
  end subroutine records_from_text

  !> A deck's `count` records of `width` characters; when they do not fit, stat /= 0 and (if
  !> asked for) an out-of-memory error naming `what`.
  pure subroutine allocate_records(records, width, count, what, stat, error)
    character(len=:), allocatable, intent(out) :: records(:)
    integer, intent(in) :: width, count
    !> What the records hold, for the message ("the deck's lines").
    character(*), intent(in) :: what
    integer, intent(out) :: stat
    type(error_t), allocatable, intent(out), optional :: error
    allocate (character(len=width) :: records(count), stat=stat)
    if (stat /= 0 .and. present(error)) call out_of_memory(error, what, int(width, int64) * count)
  end subroutine allocate_records

  !> The record of a piece of a line: the first `abs(length)` characters of `text`, after a
  !> '!' when `length` < 0 (the piece continues a comment).
  pure function record_text(text, length) result(record)
    !> The line from the piece on.
    character(*), intent(in) :: text
    !> The piece's length (< 0: a comment's continuation).
    integer, intent(in) :: length
    character(len=:), allocatable :: record
    if (length < 0) then
      record = "!"//text(1:-length)
    else
      record = text(1:length)
    end if
  end function record_text

  !> Length of the longest record of pieces `lengths` (see record_text), at least 1.
  pure integer function record_width(lengths)
    !> Piece lengths.
    integer, intent(in) :: lengths(:)
    record_width = max(1, maxval([0, abs(lengths) + merge(1, 0, lengths < 0)]))
  end function record_width

  !> The width to cut long lines at: the one from 32 up whose records take the least memory
  !> (a line longer than it taken as ceiling(length / (width - 24)) records: a value list
  !> has a place to cut every 24 characters at least), huge(1) when that is no less than
  !> records as long as the longest line.
  pure integer function chosen_cut_width(lengths, fixed) result(width)
    !> Length of each line.
    integer, intent(in) :: lengths(:)
    !> Length of the longest line that cannot be cut (a line before the first group that
    !> is not a comment).
    integer, intent(in) :: fixed
    !> Widths tried one by one (beyond: powers of two).
    integer, parameter :: tried = 4096
    !> Lines of each length up to `tried` (the lines of length 0 counted with 1).
    integer(int64) :: line_count(tried)
    integer(int64) :: cost, best, up_to
    integer, allocatable :: long_lines(:)
    integer :: longest, candidate, k, least, l
    width = huge(1)
    if (size(lengths) == 0) return
    longest = max(1, maxval(lengths))
    best = int(size(lengths), int64) * longest
    least = max(32, fixed)
    line_count = 0
    do k = 1, size(lengths)
      l = max(lengths(k), 1)
      if (l <= tried) line_count(l) = line_count(l) + 1
    end do
    long_lines = pack(lengths, lengths > tried)
    candidate = least
    do while (candidate < longest)
      ! lines no longer than the candidate: one record; longer: several
      up_to = sum(line_count(1:min(candidate, tried)))
      cost = up_to + count(long_lines <= candidate)
      ! (no line is longer than `longest`: the counts beyond it are 0)
      do l = candidate + 1, min(tried, longest)
        cost = cost + line_count(l) * ((l + candidate - 25) / (candidate - 24))
      end do
      do k = 1, size(long_lines)
        if (long_lines(k) > candidate) cost = cost + (long_lines(k) + candidate - 25) / (candidate - 24)
      end do
      cost = cost * candidate
      if (cost < best) then
        best = cost
        width = candidate
      end if
      if (candidate < tried) then
        candidate = candidate + max(1, candidate / 64)
      else
        if (candidate > longest / 2) exit
        candidate = candidate * 2
      end if
    end do
  end function chosen_cut_width

  !> Cut one line into pieces of at most `width` characters where it can be: after a comma
  !> followed (after blanks and tabs) by something else than a comma or '!', or after a
  !> blank followed by neither a blank, a tab, ',', ';', '=', '(', '*' nor '!', each outside quotes
  !> and parentheses and where the piece holds more than blanks, tabs and commas; or
  !> anywhere in a '!' comment (one after a blank, a tab or a comma, or starting the line),
  !> the next record then starting with a '!' of its own.
  !> gfortran's namelist READ takes the end of a record there as it takes the blank or the
  !> comment's end ("1,<end>2", "1 <end>2", "a = <end>1", "3* <end>0.5", "1, ! c<end>! d<end>2"
  !> read as on one line). Not so elsewhere: "1<end>, 2" reads a null value between,
  !> "a = <end>!<end>, 2" reads an element more than "a = !<end>, 2", and a value after a
  !> record "," or "" beyond an array's end is not named in the message ("Cannot match
  !> namelist object name"). A piece is longer than
  !> `width` when the line has no such place within it. A line before the first group
  !> (`in_group` false), which the READ skips, is cut only when it is a comment. The
  !> lengths of the pieces are appended to `lengths(n + 1:)` (grown as needed; negative for
  !> a piece that continues a comment, see record_text) and `n` counts them.
  pure subroutine cut_line(line, width, in_group, quote, depth, lengths, n)
    !> The line.
    character(*), intent(in) :: line
    !> Longest record wanted (characters).
    integer, intent(in) :: width
    !> The line is the first group's line or after it.
    logical, intent(in) :: in_group
    !> The quote a text continued from an earlier line is in (" " outside), at the start
    !> of the line on entry and at its end on return.
    character(len=1), intent(inout) :: quote
    !> Depth of parentheses, at the start of the line on entry and at its end on return.
    integer, intent(inout) :: depth
    !> Piece lengths of the lines so far.
    integer, allocatable, intent(inout) :: lengths(:)
    !> Pieces in `lengths`.
    integer, intent(inout) :: n
    character(len=*), parameter :: tab = achar(9)
    integer :: s, i, cut, comment_at, mark, solid_at, next
    logical :: comment
    character(len=1) :: c
    s = 1
    cut = 0
    comment = .false.
    comment_at = 0
    mark = 0
    solid_at = 0
    i = 1
    if (len(line) <= width .and. .not. in_group) then
      ! nothing to cut, no state to follow
      call append_length(lengths, n, len(line))
      return
    end if
    if (.not. in_group) then
      i = verify(line, " ")
      if (i == 0) i = len(line) + 1
      if (i <= len(line)) then
        if (line(i:i) /= "!") i = len(line) + 1
      end if
      if (i <= len(line)) then
        comment = .true.
        comment_at = i
      end if
    end if
    do while (i <= len(line))
      c = line(i:i)
      if (index(" ,"//tab, c) == 0) solid_at = i
      if (comment) then
        if (i < len(line)) cut = i
      else if (quote /= " ") then
        if (c == quote) quote = " "
      else if (depth > 0) then
        if (c == "(") depth = depth + 1
        if (c == ")") depth = depth - 1
      else if (c == "'" .or. c == '"') then
        quote = c
      else if (c == "(") then
        depth = 1
      else if (c == "!") then
        ! a comment after a value with no blank or comma between ("1.5!x"): left whole
        if (verify(line(1:i - 1), " "//tab) > 0 .and. index(" ,"//tab, line(max(i - 1, 1):max(i - 1, 1))) == 0) exit
        comment = .true.
        comment_at = i
        if (i < len(line)) cut = i
      else if (i < len(line) .and. c == "," .and. solid_at >= s) then
        ! not before blanks and a comma or a comment, nor before blanks alone
        next = verify(line(i + 1:), " "//tab)
        if (next > 0) then
          if (index(",!", line(i + next:i + next)) == 0) cut = i
        end if
      else if (i < len(line) .and. c == " " .and. solid_at >= s) then
        if (index(" ,;=(*!"//tab, line(i + 1:i + 1)) == 0) cut = i
      end if
      if (len(line) - s + 1 + mark > width .and. i >= s + width - 1 - mark .and. cut >= s) then
        ! the rest does not fit and the piece cannot grow: it ends at the last place found
        call append_length(lengths, n, merge(-(cut - s + 1), cut - s + 1, mark == 1))
        s = cut + 1
        i = cut
        if (comment_at > 0 .and. cut >= comment_at) then
          ! the next piece continues the comment
          mark = 1
          comment = .true.
        else
          ! a place to cut outside a comment is outside quotes and parentheses
          quote = " "
          depth = 0
          comment = .false.
          comment_at = 0
          mark = 0
        end if
      end if
      i = i + 1
    end do
    call append_length(lengths, n, merge(-(len(line) - s + 1), len(line) - s + 1, mark == 1))
  end subroutine cut_line

  !> One more piece length: lengths(n + 1) = length (the array grown as needed).
  pure subroutine append_length(lengths, n, length)
    !> Piece lengths.
    integer, allocatable, intent(inout) :: lengths(:)
    !> Pieces in `lengths`.
    integer, intent(inout) :: n
    !> Length of the new piece.
    integer, intent(in) :: length
    integer, allocatable :: grown(:)
    if (n == size(lengths)) then
      allocate (grown(2 * size(lengths) + 64))
      grown(1:n) = lengths(1:n)
      call move_alloc(grown, lengths)
    end if
    n = n + 1
    lengths(n) = length
  end subroutine append_length

  !> Free the deck's text once it is read (its path stays, for messages): a deck giving
  !> 10^6 values on its lines holds ~10 MB of text that a run needs no more.
  pure subroutine release_deck_text(source)
    !> The deck.
    type(deck_source_t), intent(inout) :: source
    if (allocated(source%records)) deallocate (source%records)
    if (allocated(source%first_record)) deallocate (source%first_record)
    if (allocated(source%record_length)) deallocate (source%record_length)
  end subroutine release_deck_text

  !> Number of lines of the deck.
  pure integer function deck_line_count(source)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    deck_line_count = 0
    if (allocated(source%first_record)) then
      deck_line_count = size(source%first_record) - 1
    else if (allocated(source%records)) then
      deck_line_count = size(source%records)
    end if
  end function deck_line_count

  !> The records of line `k`: first to last.
  pure subroutine line_records(source, k, first, last)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Line number.
    integer, intent(in) :: k
    !> Its first and last record.
    integer, intent(out) :: first, last
    if (allocated(source%first_record)) then
      first = source%first_record(k)
      last = source%first_record(k + 1) - 1
    else
      first = k
      last = k
    end if
  end subroutine line_records

  !> The characters of its line that record `r` holds: columns `from` to `to` of the
  !> record (the last record of a line without trailing blanks).
  pure subroutine record_part(source, r, last, from, to)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Record number.
    integer, intent(in) :: r
    !> It is the last record of its line.
    logical, intent(in) :: last
    !> First and last column of the record that belong to the line.
    integer, intent(out) :: from, to
    from = 1
    if (allocated(source%record_length)) then
      if (source%record_length(r) < 0) from = 2
      to = from - 1 + abs(source%record_length(r))
    else
      to = len(source%records(r))
    end if
    if (last) to = from - 1 + len_trim(source%records(r)(from:to))
  end subroutine record_part

  !> Length of line `k` of the deck (characters, without its terminator and trailing blanks).
  pure integer function deck_line_length(source, k)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Line number.
    integer, intent(in) :: k
    integer :: r, first, last, from, to
    call line_records(source, k, first, last)
    deck_line_length = 0
    do r = first, last
      call record_part(source, r, r == last, from, to)
      deck_line_length = deck_line_length + to - from + 1
    end do
  end function deck_line_length

  !> Line `k` of the deck as it was, without its terminator and trailing blanks.
  pure function deck_line(source, k) result(line)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Line number.
    integer, intent(in) :: k
    character(len=:), allocatable :: line
    line = line_slice(source, k, 1, huge(1))
  end function deck_line

  !> Columns `from` to `to` of line `k` (cut to the line).
  pure function line_slice(source, k, from, to) result(text)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Line number.
    integer, intent(in) :: k
    !> First and last column wanted.
    integer, intent(in) :: from, to
    character(len=:), allocatable :: text
    integer :: r, col, a, b, at, first, last, part_from, part_to
    allocate (character(len=max(0, min(to, deck_line_length(source, k)) - max(from, 1) + 1)) :: text)
    call line_records(source, k, first, last)
    col = 0
    at = 0
    do r = first, last
      ! columns col + 1 .. col + part_to - part_from + 1 of the line are in record r
      call record_part(source, r, r == last, part_from, part_to)
      a = max(from - col, 1)
      b = min(to - col, part_to - part_from + 1)
      if (b >= a) then
        text(at + 1:at + b - a + 1) = source%records(r)(part_from + a - 1:part_from + b - 1)
        at = at + b - a + 1
      end if
      col = col + part_to - part_from + 1
      if (col >= to) exit
    end do
  end function line_slice

  !> The first column from `from` on of line `k` whose character is not in `set` (`in_set`
  !> false) or is in `set` (`in_set` true); 0 when there is none.
  pure integer function line_search(source, k, from, set, in_set) result(column)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Line number.
    integer, intent(in) :: k
    !> First column looked at.
    integer, intent(in) :: from
    !> The characters.
    character(*), intent(in) :: set
    !> Look for a character in `set` (else for one not in it).
    logical, intent(in) :: in_set
    integer :: r, col, a, at, first, last, part_from, part_to, n
    call line_records(source, k, first, last)
    col = 0
    column = 0
    do r = first, last
      call record_part(source, r, r == last, part_from, part_to)
      n = part_to - part_from + 1
      a = max(from - col, 1)
      if (a <= n) then
        if (in_set) then
          at = scan(source%records(r)(part_from + a - 1:part_to), set)
        else
          at = verify(source%records(r)(part_from + a - 1:part_to), set)
        end if
        if (at > 0) then
          column = col + a - 1 + at
          return
        end if
      end if
      col = col + n
    end do
  end function line_search


end module kinetostat_deck_source
