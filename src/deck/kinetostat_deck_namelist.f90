!> Namelist lexing of a deck: the group's name, a syntax pre-check of its text before
!> gfortran's READ sees it, the probe that finds the line, assignment and variable of a
!> failed READ, and the capacities of the per-step arrays from the text's value lists.
module kinetostat_deck_namelist
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str, lower, printable, clipped, starts_with
  use kinetostat_deck_rules, only: unset_real, values_out_of_memory, deck_rules_t
  use kinetostat_deck_source, only: deck_source_t, deck_context_t, deck_line_count, deck_line, &
    deck_line_length, line_slice, line_search, line_records, record_part, record_text, cut_line, append_length, &
    record_width
  implicit none
  private
  public :: max_deck_array, title_chars, text_chars, text_bytes
  public :: read_group_name, namelist_failure, namelist_probe_t
  public :: check_namelist_syntax, longest_quoted, begin_group, deck_array_capacities, assignment_starts
  public :: comment_start

  !> Capacity of a per-step array in a deck (values beyond it are a namelist error).
  integer, parameter :: max_deck_array = 1000000
  !> Longest title of a deck, characters (a Cyrillic letter counts as one).
  integer, parameter :: title_chars = 80
  !> Longest quoted text but the title, characters (checked before the READ, so that no
  !> text variable is ever cut).
  integer, parameter :: text_chars = 32
  !> Bytes a character takes at most in UTF-8: a deck's text variable holds text_bytes
  !> times its limit in characters (text_bytes * text_chars).
  integer, parameter :: text_bytes = 4

  !> The capacity of an array of a deck group (docs/cli.md, "Capacities").
  type :: deck_capacity_t
    !> The array as gfortran's messages name it, lower case: "link", "force%table".
    character(len=:), allocatable :: array
    !> Its elements.
    integer :: size = 0
    !> What they are, plural ("links", "values (64 points)").
    character(len=:), allocatable :: noun
  end type deck_capacity_t

  !> Finds where a namelist READ of a deck failed, so that the message can name the line,
  !> the assignment and the variable (gfortran's iomsg names a token or an item number only).
  !> The mechanism READs copies of the deck cut short and closed by '/': first after each
  !> line (bisection: the first line whose copy fails), then after each assignment on that
  !> line (a copy's records are the deck's, the line cut short is cut into records as the
  !> deck's lines are). Use:
  !>     read (source%records, nml=group, iostat=probe%ios, iomsg=probe%msg)
  !>     do while (probe%retry(source))
  !>       read (probe%records, nml=group, iostat=probe%ios, iomsg=probe%msg)
  !>     end do
  !>     if (probe%failed(source, ctx, error)) return
  type :: namelist_probe_t
    !> The copy to READ next (records of an internal file).
    character(len=:), allocatable :: records(:)
    !> iostat of the last READ (of the whole deck, then of `records`).
    integer :: ios = 0
    !> iomsg of that READ.
    character(len=512) :: msg = ""
    !> iomsg of the failing READ of the whole deck, then of the failing copy.
    character(len=512) :: failure = ""
    !> Bisection: the copy through line `good` reads, the copy through line `bad` fails.
    integer :: good = 0
    !> First line whose copy fails (when `stage` > 1).
    integer :: bad = 0
    !> 1: looking for the line, 2: for the assignment on it, 5: reading that assignment
    !> alone (when it reads, the text before it is at fault: "l_over = F" makes gfortran
    !> fail at the next name), 3: trying other values in the assignment (which type the
    !> variable has), 4: done.
    integer :: stage = 4
    !> The group's opening ("&cam"), for the assignment read alone.
    character(len=:), allocatable :: header
    !> The line opening the group.
    integer :: group_line = 0
    !> Line count (stage 1), assignment index (stage 2) or other value (stage 3) in `records`.
    integer :: trying = 0
    !> Stage 3: whether the assignment reads with its first value alone, with 1, with
    !> .true., with 'x' instead of its value.
    logical :: reads(4) = .false.
    !> Start columns of the assignments on the failing line.
    integer, allocatable :: starts(:)
    !> The failing assignment on that line (0: not known).
    integer :: piece = 0
    !> Whether the READ of the whole deck failed and the probe has started (see retry).
    logical :: started = .false.
    !> The group's arrays of fixed size (see `limit`): a subscript beyond one, or more values
    !> than it holds, is reported with the limit ("link(25): at most 24 links").
    type(deck_capacity_t), allocatable :: capacities(:)
  contains
    procedure, private :: probe_limit, probe_limit_each
    generic :: limit => probe_limit, probe_limit_each
    procedure :: per_step => probe_per_step
    procedure :: retry => probe_retry
    procedure :: failed => probe_failed
    procedure :: start => probe_start
    procedure :: more => probe_more
    procedure :: take => probe_take
    procedure :: report => probe_report
  end type namelist_probe_t

contains

  !> The name of the first namelist group in the deck (lower case, without '&').
  subroutine read_group_name(source, group, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name found.
    character(len=:), allocatable, intent(out) :: group
    !> No group.
    type(error_t), allocatable, intent(out) :: error
    integer :: k, at, j
    do k = 1, deck_line_count(source)
      at = line_search(source, k, 1, " ", .false.)
      if (at == 0) cycle
      if (line_slice(source, k, at, at) /= '&') cycle
      ! the name ends before a blank, '/', ',' or '!' (or at the end of the line)
      j = line_search(source, k, at + 1, ' /,!', .true.) - 1
      if (j < 0) j = deck_line_length(source, k)
      group = lower(line_slice(source, k, at + 1, j))
      if (len(group) == 0) call fatal_error(error, exit_input, source%path//": empty namelist group name")
      return
    end do
    call fatal_error(error, exit_input, source%path// &
      ": no namelist group (a line starting with '&name') found")
  end subroutine read_group_name

  !> Turn a failed namelist READ into an input error naming file and group.
  subroutine namelist_failure(ctx, ios, msg, error)
    !> Deck and group.
    type(deck_context_t), intent(in) :: ctx
    !> iostat of the READ (non-zero).
    integer, intent(in) :: ios
    !> iomsg of the READ.
    character(*), intent(in) :: msg
    !> The input error.
    type(error_t), allocatable, intent(out) :: error
    if (ios < 0) then
      call fatal_error(error, exit_input, ctx%path//": &"//ctx%group// &
        ": namelist group not terminated by '/' (end of file)")
    else
      call fatal_error(error, exit_input, ctx%path//": &"//ctx%group//": namelist error: "// &
        trim(msg)//" (unknown variable, wrong type, or too many array values)")
    end if
  end subroutine namelist_failure

  !> After the READ of the whole deck into `ios` and `msg`: false when it read; otherwise the
  !> probe starts, and each call takes the result of the READ of the last copy (in `ios`,
  !> `msg`) and prepares the next one in `records` (see start, more); false when the place is
  !> found.
  logical function probe_retry(self, source)
    class(namelist_probe_t), intent(inout) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    integer :: whole_ios
    character(len=len(self%msg)) :: whole_msg
    probe_retry = .false.
    if (.not. self%started) then
      if (self%ios == 0) return
      whole_ios = self%ios
      whole_msg = self%msg
      call self%start(source, whole_ios, whole_msg)
      self%started = .true.
    end if
    probe_retry = self%more(source)
  end function probe_retry

  !> Whether the READ of the deck failed (after retry): then `error` names the line, the
  !> assignment and the variable.
  logical function probe_failed(self, source, ctx, error)
    class(namelist_probe_t), intent(in) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Deck and group names for the message.
    type(deck_context_t), intent(in) :: ctx
    !> The error, when the READ failed.
    type(error_t), allocatable, intent(out) :: error
    probe_failed = self%started
    if (probe_failed) call self%report(source, ctx, error)
  end function probe_failed

  !> Start looking for the place of a failed READ of the whole deck (iostat `ios`, iomsg `msg`).
  subroutine probe_start(self, source, ios, msg)
    class(namelist_probe_t), intent(inout) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> iostat of the failed READ.
    integer, intent(in) :: ios
    !> iomsg of the failed READ.
    character(*), intent(in) :: msg
    integer :: k, at
    self%failure = msg
    self%stage = 4
    self%bad = 0
    self%piece = 0
    self%reads = .false.
    if (ios < 0) return ! end of file: no line to point at
    self%good = 0
    do k = 1, deck_line_count(source)
      at = line_search(source, k, 1, " ", .false.)
      if (at == 0) cycle
      if (line_slice(source, k, at, at) == "&") then
        self%good = k - 1
        self%group_line = k
        self%header = line_slice(source, k, at, max(at, line_search(source, k, at + 1, " /,!"//achar(9), .true.) - 1))
        if (line_search(source, k, at + 1, " /,!"//achar(9), .true.) == 0) self%header = line_slice(source, k, at, huge(1))
        exit
      end if
    end do
    self%bad = deck_line_count(source)
    self%trying = 0
    self%stage = 1
  end subroutine probe_start

  !> The result of the READ of `records`.
  pure subroutine probe_take(self, ios, msg)
    class(namelist_probe_t), intent(inout) :: self
    !> iostat of the READ.
    integer, intent(in) :: ios
    !> iomsg of the READ.
    character(*), intent(in) :: msg
    self%ios = ios
    self%msg = msg
  end subroutine probe_take

  !> Take in the result of the last READ (if any) and prepare the next copy in `records`;
  !> false when the place is found.
  logical function probe_more(self, source)
    class(namelist_probe_t), intent(inout) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    character(*), parameter :: other_values(3) = [character(len=6) :: "1", ".true.", "'x'"]
    character(len=:), allocatable :: line, text, value
    integer :: mid, cut, first, last
    probe_more = .false.
    if (self%stage == 4) return
    probe_more = .true.
    call clear_read_state()
    select case (self%stage)
    case (1)
      if (self%trying > 0) then
        if (self%ios == 0) then
          self%good = self%trying
        else
          self%bad = self%trying
          self%failure = self%msg
        end if
      end if
      if (self%bad - self%good > 1) then
        mid = (self%good + self%bad) / 2
        self%trying = mid
        call line_records(source, mid, first, last)
        self%records = [character(len=len(source%records)) :: source%records(1:last), "/"]
        return
      end if
      self%stage = 2
      self%starts = assignment_starts(deck_line(source, self%bad))
      self%trying = 0
      self%piece = size(self%starts)
    case (2)
      if (self%ios /= 0) then
        self%piece = self%trying
        self%failure = self%msg
        self%stage = 5
        self%trying = 0
      end if
    case (5)
      ! the assignment read alone: when it reads, the fault is in the text before it
      if (self%ios == 0) call blame_previous(self, source)
      self%stage = 3
      self%trying = 0
    case (3)
      self%reads(self%trying) = self%ios == 0
    case default
      continue
    end select
    line = deck_line(source, self%bad)
    if (self%stage == 2) then
      if (self%trying < size(self%starts) - 1) then
        self%trying = self%trying + 1
        cut = self%starts(self%trying + 1) - 1
        call copy_through(source, self%bad, line(1:cut), self%records)
        return
      end if
      self%stage = 5
      self%trying = 0
    end if
    if (self%stage == 5) then
      if (self%piece > 0 .and. allocated(self%header)) then
        if (self%piece < size(self%starts)) then
          text = strip_comment(line(self%starts(self%piece):self%starts(self%piece + 1) - 1))
        else
          text = strip_comment(line(self%starts(self%piece):))
        end if
        self%records = [character(len=max(len(text), len(self%header), 1)) :: self%header, text, "/"]
        self%trying = 1
        return
      end if
      self%stage = 3
      self%trying = 0
    end if
    if (self%stage == 3 .and. self%piece > 0 .and. self%trying < 4) then
      self%trying = self%trying + 1
      if (self%piece < size(self%starts)) then
        text = strip_comment(line(self%starts(self%piece):self%starts(self%piece + 1) - 1))
      else
        text = strip_comment(line(self%starts(self%piece):))
      end if
      if (self%trying == 1) then
        value = first_item(text(index(text, "=") + 1:))
      else
        value = trim(other_values(self%trying - 1))
      end if
      text = line(1:self%starts(self%piece) - 1)//text(1:index(text, "="))//" "//value
      call copy_through(source, self%bad, text, self%records)
      return
    end if
    self%stage = 4
    probe_more = .false.
  end function probe_more

  !> The failing assignment reads alone, so the text before it is at fault: the assignment
  !> before it on its line, or else the last line above with text (its last assignment, or
  !> the whole line when it only continues a list of values).
  subroutine blame_previous(self, source)
    type(namelist_probe_t), intent(inout) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    integer :: k
    if (self%piece > 1) then
      self%piece = self%piece - 1
      return
    end if
    do k = self%bad - 1, self%group_line + 1, -1
      if (len(strip_comment(deck_line(source, k))) == 0) cycle
      self%bad = k
      self%starts = assignment_starts(deck_line(source, k))
      self%piece = size(self%starts)
      return
    end do
  end subroutine blame_previous

  !> A READ that succeeds. gfortran 12 carries state from a namelist READ that failed in a
  !> repeat count ("Repeat count too large", a pending count) into the next READ of an
  !> internal file, which then reads differently (a copy that fails alone reads, or the other
  !> way round, depending on where the earlier READ stopped); a successful READ in between
  !> clears it, so that each copy of the probe reads as it would alone.
  subroutine clear_read_state()
    character(len=1) :: one
    integer :: value, ios
    one = "1"
    read (one, *, iostat=ios) value
    if (ios /= 0) value = 0
  end subroutine clear_read_state

  !> A copy of the deck's records through line `bad` - 1, then `text` in place of line
  !> `bad` (cut into records as the deck's lines were), then a record "/".
  pure subroutine copy_through(source, bad, text, records)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> The line replaced.
    integer, intent(in) :: bad
    !> Its replacement.
    character(*), intent(in) :: text
    !> The copy.
    character(len=:), allocatable, intent(out) :: records(:)
    integer, allocatable :: lengths(:)
    integer :: n, k, r, depth, at, kept, last, group_line, width
    character(len=1) :: quote
    call line_records(source, bad, kept, last)
    kept = kept - 1
    allocate (lengths(1))
    n = 0
    if (source%cut_width == huge(1)) then
      ! no line was cut: one record
      call append_length(lengths, n, len(text))
    else
      ! the quote and parentheses the line starts in (followed from the first group's
      ! line on, as records_from_text does), then its pieces
      group_line = bad
      do k = 1, bad
        at = line_search(source, k, 1, " ", .false.)
        if (at == 0) cycle
        if (line_slice(source, k, at, at) == "&") then
          group_line = k
          exit
        end if
      end do
      quote = " "
      depth = 0
      do k = group_line, bad - 1
        call cut_line(deck_line(source, k), huge(1), .true., quote, depth, lengths, n)
      end do
      n = 0
      call cut_line(text, source%cut_width, bad >= group_line, quote, depth, lengths, n)
    end if
    width = max(len(source%records), record_width(lengths(1:n)))
    allocate (character(len=width) :: records(kept + n + 1))
    records(1:kept) = source%records(1:kept)
    at = 1
    do r = 1, n
      records(kept + r) = record_text(text(at:), lengths(r))
      at = at + abs(lengths(r))
    end do
    records(kept + n + 1) = "/"
  end subroutine copy_through

  !> The input error: "<deck>:<line>: &<group>: <assignment>: <reason>".
  subroutine probe_report(self, source, ctx, error)
    class(namelist_probe_t), intent(in) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Deck and group.
    type(deck_context_t), intent(in) :: ctx
    !> The input error.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: line, text, name, reason, bare
    integer :: from, to, k
    integer, allocatable :: starts(:)
    if (self%bad == 0) then
      call namelist_failure(ctx, -1, self%failure, error)
      return
    end if
    line = trim(deck_line(source, self%bad))
    from = verify(line, " ")
    to = len(line)
    if (self%piece > 0) then
      from = self%starts(self%piece)
      if (self%piece < size(self%starts)) to = self%starts(self%piece + 1) - 1
    end if
    text = strip_comment(line(max(from, 1):to))
    ! the variable: the assignment's name, or for a line of more values the last name above
    name = ""
    if (index(text, "=") > 0) then
      name = trim(adjustl(text(1:index(text, "=") - 1)))
    else
      do k = self%bad - 1, 1, -1
        name = deck_line(source, k)
        starts = assignment_starts(name)
        if (size(starts) == 0) cycle
        name = name(starts(size(starts)):)
        name = trim(adjustl(name(1:index(name, "=") - 1)))
        exit
      end do
    end if
    if (self%piece > 0 .and. index(text, "=") > 0) then
      reason = namelist_reason(name, text, self%failure, self%reads)
    else
      reason = namelist_reason(name, text, self%failure, [.false., .false., .false., .false.])
    end if
    if (index(text, "=") == 0 .and. len(name) > 0) reason = name//": "//reason
    ! "omega1 15": a variable's name and a value without '=' (not more values of the array above)
    if (index(text, "=") == 0) then
      call missing_equals(text, bare)
      if (len(bare) > 0) then
        line = trim(adjustl(text))
        reason = "missing '=' after "//bare//" (write "//bare//" = "//trim(adjustl(line(len(bare) + 1:)))//")"
      end if
    end if
    call capacity_reason(self, name, text, reason)
    call fatal_error(error, exit_input, ctx%path//":"//int_str(self%bad)//": &"//ctx%group//": "// &
      clipped(text, 60)//": "//reason)
  end subroutine probe_report

  !> Declare an array of the group with a fixed capacity (before the READ): an overflow is
  !> then reported as "link(25): at most 24 links".
  pure subroutine probe_limit(self, array, size, noun)
    class(namelist_probe_t), intent(inout) :: self
    !> The array as gfortran names it, lower case ("link", "force%table").
    character(*), intent(in) :: array
    !> Its elements.
    integer, intent(in) :: size
    !> What they are, plural ("links").
    character(*), intent(in) :: noun
    if (.not. allocated(self%capacities)) allocate (self%capacities(0))
    self%capacities = [self%capacities, deck_capacity_t(array, size, noun)]
  end subroutine probe_limit

  !> `limit` for a table of arrays of the same capacity and noun (names padded with blanks):
  !> `call probe%limit([character(7) :: "theta", "f2"], max_deck_array, "values (one per step)")`.
  pure subroutine probe_limit_each(self, arrays, capacity, noun)
    class(namelist_probe_t), intent(inout) :: self
    !> The arrays as gfortran names them, lower case.
    character(*), intent(in) :: arrays(:)
    !> Elements of each.
    integer, intent(in) :: capacity
    !> What they are, plural.
    character(*), intent(in) :: noun
    integer :: i
    do i = 1, size(arrays)
      call self%probe_limit(trim(arrays(i)), capacity, noun)
    end do
  end subroutine probe_limit_each

  !> A per-step array of the group, before the READ: allocated as long as the deck may fill
  !> it (deck_array_capacities), every element unset_real, its limit noted (max_deck_array
  !> "values (one per step)"); when there is no room, the out-of-memory error (exit 2).
  subroutine probe_per_step(self, source, ctx, name, values, error)
    class(namelist_probe_t), intent(inout) :: self
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Deck and group.
    type(deck_context_t), intent(in) :: ctx
    !> The array's variable, lower case.
    character(*), intent(in) :: name
    !> The namelist's read buffer.
    real(wp), allocatable, intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: error
    integer :: capacity(1), stat
    call self%limit(name, max_deck_array, "values (one per step)")
    capacity = deck_array_capacities(source, ctx%group, [name])
    allocate (values(capacity(1)), source=unset_real, stat=stat)
    if (stat /= 0) call values_out_of_memory(ctx, name, capacity, error)
  end subroutine probe_per_step

  !> When the failed assignment (variable `name`, text `text`) overflows an array of fixed
  !> capacity (a subscript out of range, too many values, a repeat count too large), `text`
  !> becomes that array with its subscript ("link(25)") and `reason` its limit ("at most 24
  !> links"; a subscript below 1: "subscripts run from 1 to 24").
  pure subroutine capacity_reason(self, name, text, reason)
    class(namelist_probe_t), intent(in) :: self
    !> The assignment's variable as written ("link(25)%id").
    character(*), intent(in) :: name
    !> The assignment; on return the array element when the limit applies.
    character(len=:), allocatable, intent(inout) :: text
    !> The reason; on return the limit when it applies.
    character(len=:), allocatable, intent(inout) :: reason
    character(*), parameter :: out_of_range = "out of range for namelist variable "
    character(len=:), allocatable :: array, low, part
    integer :: at, k, c, e, v, ios
    if (.not. allocated(self%capacities)) return
    at = index(self%failure, out_of_range)
    if (at > 0) then
      array = lower(trim(self%failure(at + len(out_of_range):)))
    else if (starts_with(reason, "too many values") .or. index(self%failure, "Repeat count too large") > 0) then
      array = without_subscripts(lower(name))
    else
      return
    end if
    k = 0
    do c = 1, size(self%capacities)
      if (self%capacities(c)%array == array) k = c
    end do
    if (k == 0) return
    associate (cap => self%capacities(k))
      if (at == 0) then
        text = name
        reason = "at most "//int_str(cap%size)//" "//cap%noun
        return
      end if
      ! the subscript of the array's last part in the variable: "force(1)%table(200)"
      low = lower(name)
      part = array(index(array, "%", back=.true.) + 1:)
      c = index(low, part//"(", back=.true.)
      if (c == 0) return
      c = c + len(part) + 1
      e = c
      do while (e <= len(low))
        if (index("0123456789+- ", low(e:e)) == 0) exit
        e = e + 1
      end do
      read (low(c:e - 1), *, iostat=ios) v
      if (ios /= 0) return
      text = name(1:index(low(c:), ")") + c - 1)
      if (v > cap%size) then
        reason = "at most "//int_str(cap%size)//" "//cap%noun
      else
        reason = "subscripts run from 1 to "//int_str(cap%size)//" (at most "//int_str(cap%size)//" "//cap%noun//")"
      end if
    end associate
  contains
    !> "force(1)%table(2)" -> "force%table".
    pure function without_subscripts(s) result(bare)
      character(*), intent(in) :: s
      character(len=:), allocatable :: bare
      integer :: i, depth
      bare = ""
      depth = 0
      do i = 1, len(s)
        if (s(i:i) == "(") depth = depth + 1
        if (depth == 0 .and. s(i:i) /= " ") bare = bare//s(i:i)
        if (s(i:i) == ")") depth = depth - 1
      end do
    end function without_subscripts
  end subroutine capacity_reason

  !> Whether an assignment's text without '=' starts with a variable's name followed by a
  !> blank and a value ("omega1 15", "dyad(1)%l2  0.35"): a name of two or more characters
  !> (letters, digits, '_', '%', subscripts; not T or F, the logical values) and a first
  !> value that is not a name. `name` receives that name ("" when not so).
  pure subroutine missing_equals(text, name)
    !> The assignment as written (no comment).
    character(*), intent(in) :: text
    !> The name (when true).
    character(len=:), allocatable, intent(out) :: name
    character(len=:), allocatable :: t, rest
    integer :: blank, depth, i
    name = ""
    t = trim(adjustl(text))
    if (len(t) < 3) return
    if (.not. is_letter(t(1:1))) return
    depth = 0
    blank = 0
    do i = 1, len(t)
      select case (t(i:i))
      case ("(")
        depth = depth + 1
      case (")")
        depth = depth - 1
      case (" ", achar(9))
        if (depth == 0) then
          blank = i
          exit
        end if
      case ("%", "_", ",", ":")
      case default
        if (.not. (is_letter(t(i:i)) .or. (t(i:i) >= "0" .and. t(i:i) <= "9"))) return
      end select
      if (t(i:i) == "," .and. depth == 0) return ! a list of values, not a name
    end do
    if (blank < 3) return
    rest = trim(adjustl(t(blank:)))
    if (len(rest) == 0) return
    if (is_letter(rest(1:1)) .and. .not. is_logical_text(first_item(rest))) return
    name = t(1:blank - 1)
  contains
    pure logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z")
    end function is_letter
  end subroutine missing_equals

  !> The first item of a value list (quotes respected).
  pure function first_item(value) result(item)
    character(*), intent(in) :: value
    character(len=:), allocatable :: item
    integer :: n_items, bad_item
    character(len=:), allocatable :: bad, first, last
    call scan_items(value, n_items, bad_item, bad, first, last)
    item = first
  end function first_item

  !> Why an assignment `text` of variable `name` does not read, from its text, gfortran's
  !> iomsg and what else reads in its place (`reads`: its first value alone, a number,
  !> .true., a quoted text; all false when not tried).
  pure function namelist_reason(name, text, msg, reads) result(reason)
    !> The variable ("" when not known).
    character(*), intent(in) :: name
    !> The assignment ("name = value") or a line of more values.
    character(*), intent(in) :: text
    !> gfortran's iomsg.
    character(*), intent(in) :: msg
    !> Whether the assignment reads with its first value alone, 1, .true., 'x'.
    logical, intent(in) :: reads(4)
    character(len=:), allocatable :: reason
    character(len=:), allocatable :: value, token, bad, first, last, hint
    character(*), parameter :: no_match = "Cannot match namelist object name "
    integer :: at, comma, any_comma, n_items, bad_item
    value = text
    if (index(text, "=") > 0) value = trim(adjustl(text(index(text, "=") + 1:)))
    token = ""
    at = index(msg, no_match)
    if (at > 0) token = lower(trim(msg(at + len(no_match):)))
    call scan_items(value, n_items, bad_item, bad, first, last)
    comma = decimal_comma_at(value, token, msg)
    any_comma = decimal_comma_at(value, "", "repeat")
    hint = ""
    if (any_comma > 0) hint = "; a decimal comma? write "//value(1:any_comma - 1)//"."//value(any_comma + 1:)
    if (index(msg, "out of range") > 0) then
      reason = "subscript out of range ("//trim(msg)//")"
    else if (len(name) > 0 .and. (token == lower(name) .or. .not. any(reads) .and. index(text, "=") > 0)) then
      ! gfortran says "Cannot match" or, after a list of values, "Bad data for" the previous
      ! variable; nothing at all reads in this place
      reason = "unknown variable '"//name//"' in this group (a typing error?)"
    else if (comma > 0 .and. .not. reads(3) .and. .not. reads(4)) then
      reason = "decimal comma? write "//value(1:comma - 1)//"."//value(comma + 1:)
    else if (index(msg, "verflow") > 0) then
      reason = "out of range (too large for an integer)"
    else if (reads(4) .and. scan(first(1:1), "'""") == 0) then
      reason = first//" is not a text in quotes ('...')"
    else if (reads(2) .and. bad_item > 0 .and. .not. reads(4)) then
      reason = not_a_number(bad)
    else if (reads(3) .and. .not. reads(2) .and. .not. is_logical_text(first)) then
      reason = first//" is not a logical value (.true. or .false.)"
    else if (n_items > 1 .and. (reads(1) .or. (len(token) > 0 .and. same_item(token, last)))) then
      reason = "too many values (one value, or an array's size, expected)"//hint
    else if (bad_item > 0) then
      reason = not_a_number(bad)
    else
      reason = "cannot be read ("//trim(msg)//")"
    end if
  end function namelist_reason

  !> Why a value item is not a number: text, a logical, or anything else.
  pure function not_a_number(item) result(reason)
    character(*), intent(in) :: item
    character(len=:), allocatable :: reason
    if (scan(item(1:1), "'""") > 0) then
      reason = item//" is text; a number is expected"
    else if (is_logical_text(item)) then
      reason = item//" is a logical value; a number is expected"
    else
      reason = "'"//item//"' is not a number"
    end if
  end function not_a_number

  !> The items of a value list (separated by commas or blanks, quotes respected): how many,
  !> the first that is not a number (index 0 when all are; "r*x" repeats and Inf/NaN count
  !> as numbers), the first and the last.
  pure subroutine scan_items(value, n_items, bad_item, bad, first, last)
    character(*), intent(in) :: value
    integer, intent(out) :: n_items, bad_item
    character(len=:), allocatable, intent(out) :: bad, first, last
    integer :: i, start
    character(len=1) :: quote
    character(len=:), allocatable :: word
    n_items = 0
    bad_item = 0
    bad = ""
    first = ""
    last = ""
    start = 0
    quote = " "
    do i = 1, len(value) + 1
      if (i <= len(value)) then
        if (quote /= " ") then
          if (value(i:i) == quote) quote = " "
          cycle
        end if
        if (value(i:i) == "'" .or. value(i:i) == '"') quote = value(i:i)
        if (index(", ", value(i:i)) == 0) then
          if (start == 0) start = i
          cycle
        end if
      end if
      if (start == 0) cycle
      word = value(start:i - 1)
      start = 0
      n_items = n_items + 1
      if (n_items == 1) first = word
      last = word
      if (bad_item == 0 .and. .not. is_number_text(word)) then
        bad_item = n_items
        bad = word
      end if
    end do
  end subroutine scan_items

  !> Whether gfortran's unmatched token is this item (it drops a logical's leading '.').
  pure logical function same_item(token, item)
    character(*), intent(in) :: token, item
    same_item = token == lower(item)
    if (len(item) > 1) same_item = same_item .or. (item(1:1) == "." .and. token == lower(item(2:)))
  end function same_item

  !> Whether a value item reads as a number: [r*][sign]digits[.digits][exponent], Inf, NaN.
  pure logical function is_number_text(word)
    character(*), intent(in) :: word
    character(len=:), allocatable :: w
    real(wp) :: x
    integer :: ios
    w = lower(word)
    if (index(w, "*") > 0) w = w(index(w, "*") + 1:)
    is_number_text = .false.
    if (len(w) == 0) return
    if (verify(w, "0123456789+-.ed") /= 0 .and. verify(w, "+-infatyn()x0123456789abcdef") /= 0) return
    if (scan(w, "0123456789") == 0 .and. index(w, "inf") == 0 .and. index(w, "nan") == 0) return
    read (w, *, iostat=ios) x
    is_number_text = ios == 0
  end function is_number_text

  !> Position of a decimal comma in a value ("0,11": a digit, a comma, a digit, where the
  !> READ stopped at the digits after the comma, `token`, or at a repeat count), 0 if none.
  pure integer function decimal_comma_at(value, token, msg)
    !> The assignment's value text.
    character(*), intent(in) :: value
    !> The text gfortran could not match as a name ("" if none).
    character(*), intent(in) :: token
    !> gfortran's iomsg.
    character(*), intent(in) :: msg
    integer :: i, e
    decimal_comma_at = 0
    do i = 2, len(value) - 1
      if (value(i:i) /= ",") cycle
      if (index("0123456789", value(i - 1:i - 1)) == 0 .or. index("0123456789", value(i + 1:i + 1)) == 0) cycle
      e = scan(value(i + 1:), ", *")
      if (e == 0) then
        e = len(value)
      else
        e = i + e - 1
      end if
      if (value(i + 1:e) == token .or. index(msg, "repeat") > 0) decimal_comma_at = i
      return
    end do
  end function decimal_comma_at

  !> Whether a value is a Fortran logical (.true., .false., T, F, .t., ...).
  pure logical function is_logical_text(value)
    character(*), intent(in) :: value
    character(len=:), allocatable :: v
    v = lower(value)
    is_logical_text = v == "t" .or. v == "f" .or. (len(v) > 1 .and. v(1:1) == "." .and. &
      (v(2:2) == "t" .or. v(2:2) == "f"))
  end function is_logical_text

  !> Where a line's comment starts (its '!' outside quotes), len(line) + 1 when it has none.
  pure integer function comment_start(line) result(at)
    character(*), intent(in) :: line
    character(len=1) :: quote
    integer :: i
    quote = " "
    at = len(line) + 1
    do i = 1, len(line)
      if (quote /= " ") then
        if (line(i:i) == quote) quote = " "
      else if (line(i:i) == "'" .or. line(i:i) == '"') then
        quote = line(i:i)
      else if (line(i:i) == "!") then
        at = i
        return
      end if
    end do
  end function comment_start

  !> A line without its comment ('!' outside quotes) and without a trailing comma.
  pure function strip_comment(line) result(text)
    character(*), intent(in) :: line
    character(len=:), allocatable :: text
    text = trim(adjustl(line(1:comment_start(line) - 1)))
    if (len(text) > 0) then
      if (text(len(text):) == ",") text = trim(text(1:len(text) - 1))
    end if
  end function strip_comment

  !> Start columns of the assignments on a deck line ("name =", "name(2) =", "a(1)%b ="),
  !> outside quotes and comments; a group line's '&name' is not one.
  pure function assignment_starts(line) result(starts)
    character(*), intent(in) :: line
    integer, allocatable :: starts(:)
    !> Allocated, not automatic: a line of 10^6 values would overflow the stack.
    character(len=:), allocatable :: masked
    character(len=1) :: quote
    integer :: i, j, k
    ! blank out quoted text and the comment
    masked = line
    quote = " "
    do i = 1, len(line)
      if (quote /= " ") then
        if (line(i:i) == quote) then
          quote = " "
        else
          masked(i:i) = "x"
        end if
      else if (line(i:i) == "'" .or. line(i:i) == '"') then
        quote = line(i:i)
      else if (line(i:i) == "!") then
        masked(i:) = " "
        exit
      end if
    end do
    allocate (starts(0))
    do i = 1, len_trim(masked)
      if (masked(i:i) /= "=") cycle
      call name_span(masked(1:i - 1), k, j)
      if (k > j) cycle
      starts = [starts, k]
    end do
  end function assignment_starts

  !> The start of every deck reader: the context its messages name (deck path and group),
  !> given to its validator too, and the syntax pre-check of the group's text
  !> (check_namelist_syntax) before the READ.
  subroutine begin_group(source, group, ctx, error, rules)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name, lower case, without '&'.
    character(*), intent(in) :: group
    !> The reader's context.
    type(deck_context_t), intent(out) :: ctx
    !> The syntax error (none when the text passes).
    type(error_t), allocatable, intent(out) :: error
    !> The reader's validator, naming the same deck and group.
    type(deck_rules_t), intent(out), optional :: rules
    ctx%path = source%path
    ctx%group = group
    if (present(rules)) rules%ctx = ctx
    call check_namelist_syntax(source, group, error)
  end subroutine begin_group

  !> A syntax pre-check of the deck's group `group`, before gfortran's namelist READ sees
  !> it (which crashes on some malformed text, e.g. an array or type name followed by an
  !> unclosed '(' : "&assur dyad("). From the line opening the group to its closing '/'
  !> (or '&end', '$'), outside quotes and '!' comments: every '(' closes on its line, holds
  !> only subscript or number characters and does not nest; no ')' without '('; a '='
  !> follows a variable name ("name", "name(2)", "a(1)%b"); a quote opened is closed on its
  !> line; a quoted text other than the title has at most text_chars characters (so that no
  !> text variable is cut by the READ). After the closing '/' only blanks and '!' comments
  !> (the READ would ignore the rest: "delta = 1/25, j_rotor = 0.6" would be delta = 1 and
  !> no j_rotor); a '/' between two numbers is taken for a fraction ("a fraction? write
  !> 0.04"). The error names the deck, the line, the group, the variable (the name before
  !> the last '=', or the one at fault) and the reason.
  subroutine check_namelist_syntax(source, group, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name, lower case, without '&'.
    character(*), intent(in) :: group
    !> The syntax error (none when the text passes).
    type(error_t), allocatable, intent(out) :: error
    character(len=*), parameter :: tab = achar(9)
    character(len=*), parameter :: in_parentheses = &
      "0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_+-.,:* "//tab
    character(len=:), allocatable :: line, name
    character(len=1) :: quote, c
    integer :: k, i, start, open_at, quote_line, text_length
    logical :: started
    quote = " "
    quote_line = 0
    text_length = 0
    started = .false.
    name = ""
    do k = 1, deck_line_count(source)
      line = deck_line(source, k)
      start = 1
      if (.not. started) then
        start = verify(line, " "//tab)
        if (start == 0) cycle
        if (line(start:start) /= "&") cycle
        ! the group name ends before a blank, '/', ',' or '!'
        start = start + 1
        do while (start <= len(line))
          if (index(" /,!"//tab, line(start:start)) > 0) exit
          start = start + 1
        end do
        started = .true.
      end if
      open_at = 0
      i = start
      do while (i <= len(line))
        c = line(i:i)
        if (quote /= " ") then
          if (c == quote .and. doubled_quote(line, i)) then
            ! a doubled quote stands for one quote character inside the text
            text_length = text_length + 1
            i = i + 2
            cycle
          else if (c == quote) then
            quote = " "
            if (text_length > text_chars .and. lower(name) /= "title") then
              call syntax_failure(source, group, quote_line, "", 0, name, "a text of "//int_str(text_length)// &
                " characters, more than any of its values has (at most "//int_str(text_chars)// &
                "; only title may be longer)", error)
              return
            end if
          else if (iand(iachar(c), 192) /= 128) then
            ! a character: an ASCII byte or the first byte of a UTF-8 sequence
            text_length = text_length + 1
          end if
        else if (open_at > 0) then
          if (c == ")") then
            open_at = 0
          else if (index(in_parentheses, c) == 0) then
            call syntax_failure(source, group, k, line, open_at, name, &
              "'"//printable(c)//"' inside parentheses (a subscript like dyad(2) "// &
              "or a value like (1.0, 2.0) holds numbers only)", error)
            return
          end if
        else if (c == "'" .or. c == '"') then
          quote = c
          quote_line = k
          text_length = 0
        else if (c == "!") then
          exit
        else if (c == "(") then
          open_at = i
        else if (c == ")") then
          call syntax_failure(source, group, k, line, open_at, name, "')' without '('", error)
          return
        else if (c == "=") then
          name = designator_before(line(1:i - 1))
          if (len(name) == 0) then
            call syntax_failure(source, group, k, line, open_at, name, "'=' without a variable name before it", error)
            return
          end if
        else if (c == "/" .or. c == "$" .or. c == "&") then
          call check_after_group(source, group, line, k, i, name, error)
          return
        end if
        i = i + 1
      end do
      if (open_at > 0) then
        call syntax_failure(source, group, k, line, open_at, name, &
          "unclosed '(' (a subscript like dyad(2) or a value like (1.0, 2.0) must close on its line)", error)
        return
      end if
      ! a text ends on its line (the READ would take the next line's padding into it)
      if (quote /= " ") then
        call syntax_failure(source, group, quote_line, "", 0, name, &
          "unclosed quote "//quote//" (a text must end on its line with the quote it starts with)", error)
        return
      end if
    end do
  end subroutine check_namelist_syntax

  !> The group ends at line(at:) of deck line k ('/', or '&end', '$end'): a '/' between two
  !> numbers is a fraction; after the end, blanks and '!' comments only (check_namelist_syntax).
  subroutine check_after_group(source, group, line, k, at, name, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name.
    character(*), intent(in) :: group
    !> Line k of the deck.
    character(*), intent(in) :: line
    !> Its number, and the column of the end.
    integer, intent(in) :: k, at
    !> The variable of the last '='.
    character(*), intent(in) :: name
    !> The error (none when the end is clean).
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: rest
    integer :: last, j, e
    last = at
    if (line(at:at) /= "/") then
      do while (last < len(line))
        if (verify(line(last + 1:last + 1), "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ") /= 0) exit
        last = last + 1
      end do
    else if (at > 1 .and. at < len(line)) then
      ! a number written just before and just after the '/'
      j = at - 1
      do while (j >= 1)
        if (index("0123456789.eEdD+-", line(j:j)) == 0) exit
        j = j - 1
      end do
      e = at + 1
      do while (e <= len(line))
        if (index("0123456789.eEdD+-", line(e:e)) == 0) exit
        e = e + 1
      end do
      if (j < at - 1 .and. e > at + 1) then
        if (is_number_text(line(j + 1:at - 1)) .and. is_number_text(line(at + 1:e - 1))) then
          call syntax_failure(source, group, k, "", 0, name//" = "//line(j + 1:e - 1), &
            fraction_hint(line(j + 1:at - 1), line(at + 1:e - 1)), error)
          return
        end if
      end if
    end if
    rest = adjustl(line(last + 1:))
    j = k
    do
      if (len_trim(rest) > 0) then
        if (rest(1:1) /= "!") then
          call fatal_error(error, exit_input, source%path//":"//int_str(j)//": &"//group//": "// &
            clipped(printable(trim(rest)), 60)//": text after the group's closing '/' (it would be ignored: "// &
            "move it before the '/', or make it a comment with '!')")
          return
        end if
      end if
      j = j + 1
      if (j > deck_line_count(source)) exit
      rest = adjustl(deck_line(source, j))
    end do
  end subroutine check_after_group

  !> The message for a value written as a fraction "a/b": "a fraction? write 0.04".
  pure function fraction_hint(numerator, denominator) result(hint)
    !> The texts before and after the '/' (numbers).
    character(*), intent(in) :: numerator, denominator
    character(len=:), allocatable :: hint
    real(wp) :: a, b, q, back
    character(len=40) :: buf
    integer :: ios, digits
    hint = "a fraction? a namelist value cannot be one (the '/' would end the group)"
    read (numerator, *, iostat=ios) a
    if (ios /= 0) return
    read (denominator, *, iostat=ios) b
    if (ios /= 0 .or. .not. b /= 0.0_wp) return
    q = a / b
    if (.not. abs(q) <= huge(q)) return
    ! the shortest fixed or exponent form (up to 12 significant digits) that reads back to q
    do digits = 1, 12
      write (buf, '(es40.' // int_str(digits - 1) // 'e3)') q
      read (buf, *) back
      if (abs(back - q) <= 1.0e-12_wp * abs(q)) exit
    end do
    if (abs(q) >= 1.0e-4_wp .and. abs(q) < 1.0e7_wp .or. q == 0.0_wp) then
      write (buf, '(f40.' // int_str(max(0, digits - 1 - floor(log10(max(abs(q), tiny(q)))))) // ')') q
      buf = adjustl(buf)
      if (buf(len_trim(buf):len_trim(buf)) == ".") buf(len_trim(buf):) = " "
    else
      write (buf, '(es40.' // int_str(max(1, digits - 1)) // 'e3)') q
    end if
    hint = "a fraction? write "//trim(adjustl(buf))
  end function fraction_hint

  !> The pre-check's error at line `at`: "<deck>:<at>: &<group>: <variable>: <reason>"; the
  !> variable is the name written just before an unclosed '(' (at `open_at` of `line`, 0:
  !> none) when there is one, else `name` (the last assigned).
  pure subroutine syntax_failure(source, group, at, line, open_at, name, reason, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name.
    character(*), intent(in) :: group
    !> Line of the fault.
    integer, intent(in) :: at
    !> Its text ("" when not needed).
    character(*), intent(in) :: line
    !> Column of an unclosed '(' on it (0: none).
    integer, intent(in) :: open_at
    !> The variable of the last '=' ("" when none yet).
    character(*), intent(in) :: name
    !> Why.
    character(*), intent(in) :: reason
    !> The input error.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: who
    integer :: j, e
    who = name
    if (open_at > 0) then
      ! the name written just before the '(' (a designator, or a value's text)
      call name_span(line(1:open_at - 1), j, e)
      if (e >= j) then
        if (len(who) == 0 .or. index(line(open_at:), "=") > 0 .or. e == open_at - 1) who = line(j:open_at)
      end if
    end if
    if (len(who) == 0) who = "(no variable yet)"
    call fatal_error(error, exit_input, source%path//":"//int_str(at)//": &"//group//": "// &
      clipped(printable(who), 60)//": "//reason)
  end subroutine syntax_failure

  !> The name with its subscripts and components at the end of `text` (trailing blanks and
  !> tabs skipped): text(first:last), empty (first > last) when `text` does not end with one.
  pure subroutine name_span(text, first, last)
    !> The text before a '=' or a '('.
    character(*), intent(in) :: text
    !> First and last character of the name.
    integer, intent(out) :: first, last
    last = len(text)
    do while (last >= 1)
      if (index(" "//achar(9), text(last:last)) == 0) exit
      last = last - 1
    end do
    first = last
    do while (first >= 1)
      if (index("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_%()", text(first:first)) == 0) exit
      first = first - 1
    end do
    first = first + 1
  end subroutine name_span

  !> The variable name written just before a '=' ("dyad(2)%l2" of "  dyad(2)%l2 "), "" when
  !> the text before the '=' does not end with one.
  pure function designator_before(text) result(name)
    !> The line up to the '='.
    character(*), intent(in) :: text
    character(len=:), allocatable :: name
    character(len=*), parameter :: tab = achar(9)
    integer :: e, j
    name = ""
    e = len(text)
    do while (e >= 1)
      if (index(" "//tab, text(e:e)) == 0) exit
      e = e - 1
    end do
    j = e
    do while (j >= 1)
      if (index("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_%(),:+- ", text(j:j)) == 0) exit
      if (text(j:j) == " ") then
        ! a blank inside a subscript ("a( 1 )") or before one ("f5c (3)") only
        if (count_char(text(j + 1:e), ")") <= count_char(text(j + 1:e), "(") .and. text(j + 1:j + 1) /= "(") exit
      end if
      j = j - 1
    end do
    do while (j < e)
      if (index("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ", text(j + 1:j + 1)) > 0) exit
      j = j + 1
    end do
    if (j < e) name = text(j + 1:e)
  contains
    pure integer function count_char(t, ch)
      character(*), intent(in) :: t
      character(len=1), intent(in) :: ch
      integer :: m
      count_char = 0
      do m = 1, len(t)
        if (t(m:m) == ch) count_char = count_char + 1
      end do
    end function count_char
  end function designator_before

  !> Whether the quote character at `line(i:i)` is doubled (`''` inside '...', `""` inside
  !> "..."): one quote character of the text, not its end.
  pure logical function doubled_quote(line, i)
    character(*), intent(in) :: line
    integer, intent(in) :: i
    doubled_quote = .false.
    if (i < len(line)) doubled_quote = line(i + 1:i + 1) == line(i:i)
  end function doubled_quote

  !> Length of the longest quoted text in the deck (quotes excluded, a doubled quote
  !> counted once; at least 1): a character variable of this length holds any text the
  !> deck gives, without a stack-sized buffer.
  pure integer function longest_quoted(source) result(longest)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    character(len=:), allocatable :: line
    character(len=1) :: quote
    integer :: k, i, length
    longest = 1
    quote = " "
    length = 0
    do k = 1, deck_line_count(source)
      line = deck_line(source, k)
      i = 1
      do while (i <= len(line))
        if (quote /= " ") then
          if (line(i:i) /= quote) then
            length = length + 1
          else if (doubled_quote(line, i)) then
            ! one quote character of the text: count it, step over both
            length = length + 1
            i = i + 1
          else
            quote = " "
            longest = max(longest, length)
          end if
        else if (line(i:i) == "'" .or. line(i:i) == '"') then
          quote = line(i:i)
          length = 0
        else if (line(i:i) == "!") then
          exit
        end if
        i = i + 1
      end do
      if (quote /= " ") length = length + 1
    end do
    longest = max(longest, length)
  end function longest_quoted

  !> All required real variables that the deck did not set, in one message:

  !> Capacities for the per-step arrays `names` of namelist group `group`: for each, an upper
  !> bound on the highest element the deck's text can assign (from its value lists, repeat
  !> counts `r*c`, null values and subscripts `name(i)`), at least 1 and at most
  !> max_deck_array. An array sized so reads exactly as one of max_deck_array elements (a
  !> deck giving more values than that fails the same way), without the 10^6-element buffer.
  !> The scan starts after the first line opening the group ('&group'), skips quoted strings
  !> (which may span lines) and '!' comments, and stops at '/'. Each '=' closes the value
  !> list before it and opens one for the designator written just before it; a list's count
  !> includes that following designator, so the bound may exceed the truth by one or more
  !> (never fall short of it). Not `pure` only because its internal steps share the scan's
  !> state; it has no side effects.
  function deck_array_capacities(source, group, names) result(capacity)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name, lower case, without '&'.
    character(*), intent(in) :: group
    !> Array names, lower case (trailing blanks ignored).
    character(*), intent(in) :: names(:)
    !> Elements to allocate for each array.
    integer :: capacity(size(names))
    !> Longest token kept (a longer one counts as a huge repeat count or subscript).
    integer, parameter :: token_max = 128
    !> Cap of counts (well above max_deck_array, far below overflow).
    integer(int64), parameter :: count_cap = 1000000000000_int64
    character(len=*), parameter :: tab = achar(9)
    integer(int64) :: bound(size(names)), slots, first
    character(len=token_max) :: token, last, before_last
    integer :: token_len, last_len, before_last_len, depth, line, i, start, target, col, r
    integer :: first_piece, last_piece, first_column, last_column
    logical :: truncated, last_truncated, before_last_truncated, value_since_comma
    character(len=1) :: quote, c

    bound = 0
    capacity = 1
    call find_group(line, start)
    if (line == 0) return
    target = 0
    first = 1
    slots = 0
    value_since_comma = .false.
    token_len = 0; last_len = 0; before_last_len = 0
    truncated = .false.; last_truncated = .false.; before_last_truncated = .false.
    depth = 0
    quote = " "
    scan: do while (line <= deck_line_count(source))
      ! the line's records in turn, `col` its columns before record r
      col = 0
      call line_records(source, line, first_piece, last_piece)
      pieces: do r = first_piece, last_piece
        call record_part(source, r, r == last_piece, first_column, last_column)
        associate (text => source%records(r))
          do i = max(start - col, 1) + first_column - 1, last_column
            c = text(i:i)
            if (quote /= " ") then
              call add_char(c)
              if (c == quote) quote = " "
            else if (depth > 0) then
              call add_char(c)
              if (c == "(") depth = depth + 1
              if (c == ")") depth = depth - 1
            else if (c == "'" .or. c == '"') then
              quote = c
              call add_char(c)
            else if (c == "(") then
              depth = 1
              call add_char(c)
            else if (c == "!") then
              ! gfortran may take a comment after a separator for a null value: count one
              call end_token()
              slots = min(slots + 1, count_cap)
              exit pieces
            else if (c == "/") then
              call end_token()
              exit scan
            else if (c == " " .or. c == tab) then
              call end_token()
            else if (c == "," .or. c == ";") then
              call end_token()
              ! a separator after a separator (or right after '=') is a null value
              if (.not. value_since_comma) slots = min(slots + 1, count_cap)
              value_since_comma = .false.
            else if (c == "=") then
              call end_token()
              call close_list()
              call open_list()
            else
              call add_char(c)
            end if
          end do
        end associate
        col = col + last_column - first_column + 1
      end do pieces
      if (quote == " " .and. depth == 0) then
        ! the end of a line separates values like a comma (gfortran: "1<eol>, 2" is 1, null, 2);
        ! counted as a null when no value came since the last separator (may over-count)
        call end_token()
        if (.not. value_since_comma) slots = min(slots + 1, count_cap)
        value_since_comma = .false.
      end if
      line = line + 1
      start = 1
    end do scan
    call close_list()
    capacity = int(max(1_int64, min(bound, int(max_deck_array, int64))))

  contains

    !> Line and column just after '&group' on the first line opening the group (0 when none).
    subroutine find_group(line, start)
      integer, intent(out) :: line, start
      integer :: k, at, j
      do k = 1, deck_line_count(source)
        at = line_search(source, k, 1, " "//tab, .false.)
        if (at == 0) cycle
        if (line_slice(source, k, at, at) /= "&") cycle
        j = line_search(source, k, at + 1, " /,!"//tab, .true.)
        if (j == 0) j = deck_line_length(source, k) + 1
        if (lower(line_slice(source, k, at + 1, j - 1)) /= group) cycle
        line = k
        start = j
        return
      end do
      line = 0
      start = 1
    end subroutine find_group

    !> One more character of the current token.
    subroutine add_char(ch)
      character(len=1), intent(in) :: ch
      if (token_len < token_max) then
        token_len = token_len + 1
        token(token_len:token_len) = ch
      else
        truncated = .true.
      end if
    end subroutine add_char

    !> The current token is complete: it is a value (or the next designator) of the list.
    subroutine end_token()
      if (token_len == 0) return
      slots = min(slots + repeat_count(token(1:token_len), truncated), count_cap)
      value_since_comma = .true.
      before_last = last; before_last_len = last_len; before_last_truncated = last_truncated
      last = token; last_len = token_len; last_truncated = truncated
      token_len = 0
      truncated = .false.
    end subroutine end_token

    !> The values counted since the last '=' end at element first + slots - 1 of the array.
    subroutine close_list()
      ! the designator's element itself must exist even when no value follows ("a(5) = /")
      if (target > 0) bound(target) = max(bound(target), min(first + max(slots, 1_int64) - 1, count_cap))
    end subroutine close_list

    !> A '=' follows the designator last read (a subscript written apart, "f5c (3)", is
    !> joined to its name): the array it names, if one of `names`, and its first element.
    subroutine open_list()
      character(len=:), allocatable :: designator
      logical :: cut
      integer :: paren, k
      integer(int64) :: number
      target = 0
      first = 1
      slots = 0
      value_since_comma = .false.
      if (last_len == 0) return
      designator = lower(last(1:last_len))
      cut = last_truncated
      if (designator(1:1) == "(" .and. before_last_len > 0) then
        designator = lower(before_last(1:before_last_len))//designator
        cut = cut .or. before_last_truncated
      end if
      last_len = 0
      before_last_len = 0
      if (index(designator, "%") > 0) return
      paren = index(designator, "(")
      if (paren == 0) paren = len(designator) + 1
      target = findloc([(trim(names(k)) == designator(1:paren - 1), k=1, size(names))], .true., dim=1)
      if (target == 0) return
      ! first element: the largest number in the subscript (a section's upper end)
      number = 0
      do k = paren + 1, len(designator)
        if (designator(k:k) >= "0" .and. designator(k:k) <= "9") then
          number = min(number * 10 + (iachar(designator(k:k)) - iachar("0")), count_cap)
          first = max(first, number)
        else
          number = 0
        end if
      end do
      if (cut) first = count_cap
    end subroutine open_list

    !> Values a token stands for: r for a repeat "r*c" or "r*", else 1.
    pure integer(int64) function repeat_count(tok, cut)
      character(*), intent(in) :: tok
      !> The token was longer than kept.
      logical, intent(in) :: cut
      integer :: star, k
      repeat_count = 1
      star = verify(tok, "0123456789")
      if (star == 0) then
        ! all digits: a long run may continue with '*' beyond what was kept
        if (cut) repeat_count = count_cap
        return
      end if
      if (star == 1 .or. tok(star:star) /= "*") return
      repeat_count = 0
      do k = 1, star - 1
        repeat_count = min(repeat_count * 10 + (iachar(tok(k:k)) - iachar("0")), count_cap)
      end do
    end function repeat_count
  end function deck_array_capacities


end module kinetostat_deck_namelist
