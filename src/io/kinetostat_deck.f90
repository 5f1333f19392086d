!> Deck (namelist file) plumbing shared by every mechanism: reading the deck once into
!> memory, finding the group name, turning namelist I/O errors into messages, and
!> validation rules that name the file, the group, the variable and the reason.
module kinetostat_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: real_str, int_str, number_str, lower
  use kinetostat_posix, only: read_standard_input
  implicit none
  private
  public :: deck_context_t, unset_real, unset_bits, max_deck_array, max_steps
  public :: deck_source_t, load_deck, deck_source_from_text, stdin_deck_path, stdin_deck_name
  public :: read_group_name, namelist_failure, deck_error
  public :: is_set, require_set, require_positive, require_nonnegative, require_rule
  public :: is_whole_in, require_whole
  public :: optional_default, count_values, steps_over_turn, write_template_lines, deck_array_capacity

  !> Bit pattern of `unset_real`: a quiet NaN with a payload. A NaN typed in a deck
  !> ("nan", "NaN(0x1)") reads as the plain quiet NaN 7FF8000000000000, so no deck can
  !> produce this value.
  integer(int64), parameter :: unset_bits = int(z'7FF80000DEAD0001', int64)
  !> Sentinel of a real deck variable the deck did not set (compare with `is_set` only:
  !> being a NaN, it is unequal to everything, itself included). Integer deck variables
  !> are read as reals too (see `require_whole`), so they share this sentinel.
  !> A protected variable, not a parameter: gfortran's .mod files keep a NaN parameter
  !> without its payload, so a parameter would arrive in other modules as the plain NaN
  !> (for a derived type's default initialisation, use transfer(unset_bits, 1.0_wp) in
  !> the module that declares the variables, see kinetostat_assur_deck).
  real(wp), protected :: unset_real = transfer(unset_bits, 1.0_wp)
  !> The deck path that means standard input.
  character(*), parameter :: stdin_deck_path = "-"
  !> Name of a deck read from standard input, in messages and in the table's DECK line.
  character(*), parameter :: stdin_deck_name = "<stdin>"
  !> Capacity of a per-step array in a deck (values beyond it are a namelist error).
  integer, parameter :: max_deck_array = 1000000
  !> Largest number of steps a run may have.
  integer, parameter :: max_steps = 1000000

  !> A deck read into memory: its lines, ready for an internal namelist READ.
  type :: deck_source_t
    !> Name of the deck in messages (the file path as given, or e.g. "<stdin>").
    character(len=:), allocatable :: path
    !> The deck's lines without line terminators (LF, CRLF) and without a leading UTF-8
    !> byte-order mark, blank-padded to the longest line (length at least 1).
    character(len=:), allocatable :: lines(:)
  end type deck_source_t

  !> Where a deck value comes from: file and namelist group (for messages).
  type :: deck_context_t
    !> Deck file path as given on the command line.
    character(len=:), allocatable :: path
    !> Namelist group name, lower case, without '&'.
    character(len=:), allocatable :: group
  end type deck_context_t

contains

  !> A template deck held as lines (trailing blanks dropped).
  pure subroutine write_template_lines(out, lines)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> The deck's lines.
    character(*), intent(in) :: lines(:)
    integer :: i
    do i = 1, size(lines)
      call out%put(trim(lines(i)))
    end do
  end subroutine write_template_lines

  !> Read a whole deck file into memory (any line length, LF or CRLF line ends, with or
  !> without a final newline, optional UTF-8 byte-order mark). The path "-" reads standard
  !> input to its end (the deck is then named "<stdin>"); a pipe given as a path
  !> (/dev/stdin, /dev/fd/N, a FIFO) is read to its end as well: read once, never rewound.
  subroutine load_deck(path, source, error)
    !> Deck file, or "-" for standard input.
    character(*), intent(in) :: path
    !> The deck's lines.
    type(deck_source_t), intent(out) :: source
    !> Set when the file cannot be opened or read.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: text
    character(len=1) :: byte
    integer :: unit, ios, n
    integer(int64) :: file_size
    character(len=512) :: msg
    if (path == stdin_deck_path) then
      if (.not. read_standard_input(text)) then
        call fatal_error(error, exit_input, stdin_deck_name//": cannot read the deck from standard input")
        return
      end if
      call deck_source_from_text(stdin_deck_name, text, source)
      return
    end if
    open (newunit=unit, file=path, status='old', action='read', access='stream', form='unformatted', &
          iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fatal_error(error, exit_input, path//": cannot open deck: "//trim(msg))
      return
    end if
    inquire (unit=unit, size=file_size)
    if (file_size > 0) then
      allocate (character(len=file_size) :: text)
      read (unit, iostat=ios, iomsg=msg) text
    else
      ! size unknown (pipe, device) or reported as 0: read byte by byte until the end
      allocate (character(len=4096) :: text)
      n = 0
      do
        read (unit, iostat=ios, iomsg=msg) byte
        if (ios /= 0) exit
        n = n + 1
        if (n > len(text)) text = text//repeat(' ', len(text))
        text(n:n) = byte
      end do
      if (is_iostat_end(ios)) ios = 0
      text = text(1:n)
    end if
    close (unit)
    if (ios /= 0) then
      call fatal_error(error, exit_input, path//": cannot read deck: "//trim(msg))
      return
    end if
    call deck_source_from_text(path, text, source)
  end subroutine load_deck

  !> A deck from text held in memory: lines split at LF, a CR before each LF dropped, a
  !> leading UTF-8 byte-order mark dropped; a last line without LF is kept.
  pure subroutine deck_source_from_text(name, text, source)
    !> Name of the deck in messages.
    character(*), intent(in) :: name
    !> The deck's text.
    character(*), intent(in) :: text
    !> The deck's lines.
    type(deck_source_t), intent(out) :: source
    character(len=*), parameter :: bom = char(239)//char(187)//char(191)
    character(len=*), parameter :: lf = achar(10), cr = achar(13)
    integer :: first, n_lines, longest, i, line_start, line_end, k
    first = 1
    if (len(text) >= 3) then
      if (text(1:3) == bom) first = 4
    end if
    ! count lines and the longest one
    n_lines = 0
    longest = 1
    line_start = first
    do while (line_start <= len(text))
      call next_line(line_start, line_end, i)
      n_lines = n_lines + 1
      longest = max(longest, line_end - line_start + 1)
      line_start = i
    end do
    source%path = name
    allocate (character(len=longest) :: source%lines(n_lines))
    line_start = first
    do k = 1, n_lines
      call next_line(line_start, line_end, i)
      source%lines(k) = text(line_start:line_end)
      line_start = i
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
  end subroutine deck_source_from_text

  !> Capacity for a per-step array of this deck: enough for every value the deck can give
  !> it, without max_deck_array elements filled before reading. Each value takes at least
  !> one character of the text, a repeat count r*c gives r values and a subscript f(i)
  !> reaches element i, so the text's length plus the sum of every whole number written in
  !> it (counts, subscripts and anything else) bounds what a namelist READ can store;
  !> capped at max_deck_array (beyond it a deck gets the same namelist error as before).
  pure integer function deck_array_capacity(source)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    integer(int64) :: total, run
    integer :: k, i, c
    total = 0
    do k = 1, size(source%lines)
      run = 0
      do i = 1, len_trim(source%lines(k))
        c = iachar(source%lines(k)(i:i)) - iachar("0")
        if (c >= 0 .and. c <= 9) then
          run = min(10 * run + c, int(max_deck_array, int64))
        else
          total = total + run
          run = 0
        end if
      end do
      total = min(total + run + len_trim(source%lines(k)) + 1, int(max_deck_array, int64))
    end do
    deck_array_capacity = int(total)
  end function deck_array_capacity

  !> The name of the first namelist group in the deck (lower case, without '&').
  subroutine read_group_name(source, group, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Group name found.
    character(len=:), allocatable, intent(out) :: group
    !> No group.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: line
    integer :: k, i, j
    do k = 1, size(source%lines)
      line = trim(adjustl(source%lines(k)))
      if (len(line) == 0) cycle
      if (line(1:1) /= '&') cycle
      j = len(line)
      do i = 2, len(line)
        if (index(' /,!', line(i:i)) > 0) then
          j = i - 1
          exit
        end if
      end do
      group = lower(line(2:j))
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

  !> An input error about one variable: "<deck>: &<group>: <name>: <reason>".
  pure subroutine deck_error(ctx, name, reason, error)
    !> Deck and group.
    type(deck_context_t), intent(in) :: ctx
    !> Variable name.
    character(*), intent(in) :: name
    !> Why it is rejected.
    character(*), intent(in) :: reason
    !> The input error.
    type(error_t), allocatable, intent(out) :: error
    call fatal_error(error, exit_input, ctx%path//": &"//ctx%group//": "//name//": "//reason)
  end subroutine deck_error

  !> Whether the deck set a real variable (its bits differ from `unset_real`'s).
  elemental logical function is_set(x)
    !> Deck variable, initialised to `unset_real` before the READ.
    real(wp), intent(in) :: x
    is_set = transfer(x, 0_int64) /= unset_bits
  end function is_set

  !> Whether `x` is a whole number from `lo` to `hi` (so nint(x) is exact and in range).
  elemental logical function is_whole_in(x, lo, hi)
    !> Deck value.
    real(wp), intent(in) :: x
    !> Smallest and largest value accepted.
    integer, intent(in) :: lo, hi
    is_whole_in = .false.
    if (.not. ieee_is_finite(x)) return
    is_whole_in = x == aint(x) .and. x >= real(lo, wp) .and. x <= real(hi, wp)
  end function is_whole_in

  !> An integer deck variable, read as a real: it must be set and a whole number from `lo`
  !> to `hi` ("must be a whole number from LO to HI (got X)"). Reading integers as reals
  !> keeps the "not set" sentinel out of reach and turns out-of-range or fractional input
  !> into a message naming the variable.
  subroutine require_whole(ctx, name, x, lo, hi, value, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    !> Deck value.
    real(wp), intent(in) :: x
    !> Smallest and largest value accepted.
    integer, intent(in) :: lo, hi
    !> The value as an integer (`lo` on error).
    integer, intent(out) :: value
    type(error_t), allocatable, intent(out) :: error
    value = lo
    if (.not. is_set(x)) then
      call deck_error(ctx, name, "missing (required variable)", error)
    else if (.not. is_whole_in(x, lo, hi)) then
      call deck_error(ctx, name, "must be a whole number from "//int_str(lo)//" to "//int_str(hi)// &
        " (got "//number_str(x)//")", error)
    else
      value = nint(x)
    end if
  end subroutine require_whole

  !> Required real: present and finite.
  subroutine require_set(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    if (.not. is_set(x)) then
      call deck_error(ctx, name, "missing (required variable)", error)
    else if (.not. ieee_is_finite(x)) then
      call deck_error(ctx, name, "must be a finite number (got "//real_str(x)//")", error)
    end if
  end subroutine require_set

  !> Required real, finite and > 0.
  subroutine require_positive(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    call require_set(ctx, name, x, error)
    if (allocated(error)) return
    if (.not. x > 0.0_wp) call deck_error(ctx, name, "must be > 0 (got "//real_str(x)//")", error)
  end subroutine require_positive

  !> Required real, finite and >= 0.
  subroutine require_nonnegative(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    call require_set(ctx, name, x, error)
    if (allocated(error)) return
    if (.not. x >= 0.0_wp) call deck_error(ctx, name, "must be >= 0 (got "//real_str(x)//")", error)
  end subroutine require_nonnegative

  !> A rule between variables: when `ok` is false, report `reason` against `name`.
  pure subroutine require_rule(ctx, name, ok, reason, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    logical, intent(in) :: ok
    character(*), intent(in) :: reason
    type(error_t), allocatable, intent(out) :: error
    if (.not. ok) call deck_error(ctx, name, reason, error)
  end subroutine require_rule

  !> An optional real: its default when unset (validity is checked by the caller).
  elemental function optional_default(x, default) result(y)
    real(wp), intent(in) :: x, default
    real(wp) :: y
    if (is_set(x)) then
      y = x
    else
      y = default
    end if
  end function optional_default

  !> Number of values a deck gave for an array: the leading set entries, which must be
  !> finite and followed by no set entry (no gaps).
  subroutine count_values(ctx, name, values, count, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: values(:)
    !> How many values were given.
    integer, intent(out) :: count
    type(error_t), allocatable, intent(out) :: error
    integer :: i
    count = 0
    do i = 1, size(values)
      if (.not. is_set(values(i))) exit
      count = i
    end do
    if (count < size(values)) then
      if (any(is_set(values(count + 1:)))) then
        call deck_error(ctx, name, "values must be given without gaps (element "// &
          int_str(count + 1)//" is missing)", error)
        return
      end if
    end if
    do i = 1, count
      if (.not. ieee_is_finite(values(i))) then
        call deck_error(ctx, name//"("//int_str(i)//")", "must be a finite number (got "// &
          real_str(values(i))//")", error)
        return
      end if
    end do
  end subroutine count_values

  !> Number of steps of a crank stepped by `dphi` (deg): `n` when the deck set it
  !> (a whole number from 1 to max_steps), otherwise floor(360/dphi) + 1, which must not
  !> exceed max_steps (computed in real arithmetic, so a tiny dphi cannot overflow).
  !> `dphi` must be > 0.
  subroutine steps_over_turn(ctx, dphi, n_given, n, error)
    type(deck_context_t), intent(in) :: ctx
    !> Crank step, deg (validated > 0 here).
    real(wp), intent(in) :: dphi
    !> `n` from the deck (a real holding a whole number), or unset_real.
    real(wp), intent(in) :: n_given
    !> Number of steps.
    integer, intent(out) :: n
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: n_real
    n = 0
    call require_positive(ctx, "dphi", dphi, error)
    if (allocated(error)) return
    if (is_set(n_given)) then
      call require_whole(ctx, "n", n_given, 1, max_steps, n, error)
    else
      n_real = aint(360.0_wp / dphi * (1.0_wp + 1.0e-12_wp)) + 1.0_wp
      if (.not. n_real <= real(max_steps, wp)) then
        call deck_error(ctx, "dphi", "too small (got "//real_str(dphi)//"): 360/dphi + 1 exceeds "// &
          int_str(max_steps)//" steps", error)
        return
      end if
      n = nint(n_real)
    end if
  end subroutine steps_over_turn

end module kinetostat_deck
