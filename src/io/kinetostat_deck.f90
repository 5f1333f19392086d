!> Deck (namelist file) plumbing shared by every mechanism: finding the group name,
!> opening, turning namelist I/O errors into messages, and validation rules that name
!> the file, the group, the variable and the reason.
module kinetostat_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: real_str, int_str, lower
  implicit none
  private
  public :: deck_context_t, unset_real, unset_int, max_deck_array, max_steps
  public :: read_group_name, open_deck, namelist_failure, deck_error
  public :: is_set, require_set, require_positive, require_nonnegative, require_rule
  public :: optional_default, count_values, steps_over_turn, write_template_lines

  !> Sentinel of a real deck variable the deck did not set.
  real(wp), parameter :: unset_real = -huge(1.0_wp)
  !> Sentinel of an integer deck variable the deck did not set.
  integer, parameter :: unset_int = -huge(1)
  !> Capacity of a per-step array in a deck (values beyond it are a namelist error).
  integer, parameter :: max_deck_array = 1000000
  !> Largest number of steps a run may have.
  integer, parameter :: max_steps = 1000000

  !> Where a deck value comes from: file and namelist group (for messages).
  type :: deck_context_t
    !> Deck file path as given on the command line.
    character(len=:), allocatable :: path
    !> Namelist group name, lower case, without '&'.
    character(len=:), allocatable :: group
  end type deck_context_t

  interface is_set
    module procedure is_set_real, is_set_int
  end interface is_set

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

  !> The name of the first namelist group in the deck (lower case, without '&').
  subroutine read_group_name(path, group, error)
    !> Deck file.
    character(*), intent(in) :: path
    !> Group name found.
    character(len=:), allocatable, intent(out) :: group
    !> Unreadable file or no group.
    type(error_t), allocatable, intent(out) :: error
    character(len=1024) :: line
    integer :: unit, ios, i, j
    call open_deck(path, unit, error)
    if (allocated(error)) return
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      line = adjustl(line)
      if (line(1:1) /= '&') cycle
      j = len_trim(line)
      do i = 2, len_trim(line)
        if (index(' /,!', line(i:i)) > 0) then
          j = i - 1
          exit
        end if
      end do
      group = lower(line(2:j))
      close (unit)
      if (len(group) == 0) call fatal_error(error, exit_input, path//": empty namelist group name")
      return
    end do
    close (unit)
    call fatal_error(error, exit_input, path//": no namelist group (a line starting with '&name') found")
  end subroutine read_group_name

  !> Open a deck for reading.
  subroutine open_deck(path, unit, error)
    !> Deck file.
    character(*), intent(in) :: path
    !> Unit opened.
    integer, intent(out) :: unit
    !> Set when the file cannot be opened.
    type(error_t), allocatable, intent(out) :: error
    integer :: ios
    character(len=512) :: msg
    open (newunit=unit, file=path, status='old', action='read', form='formatted', iostat=ios, iomsg=msg)
    if (ios /= 0) call fatal_error(error, exit_input, path//": cannot open deck: "//trim(msg))
  end subroutine open_deck

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

  elemental logical function is_set_real(x)
    real(wp), intent(in) :: x
    is_set_real = x /= unset_real
  end function is_set_real

  elemental logical function is_set_int(i)
    integer, intent(in) :: i
    is_set_int = i /= unset_int
  end function is_set_int

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
  !> (must be 1..max_steps), otherwise floor(360/dphi) + 1. `dphi` must be > 0.
  subroutine steps_over_turn(ctx, dphi, n_given, n, error)
    type(deck_context_t), intent(in) :: ctx
    !> Crank step, deg (validated > 0 here).
    real(wp), intent(in) :: dphi
    !> `n` from the deck, or unset_int.
    integer, intent(in) :: n_given
    !> Number of steps.
    integer, intent(out) :: n
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: n_real
    n = 0
    call require_positive(ctx, "dphi", dphi, error)
    if (allocated(error)) return
    if (is_set(n_given)) then
      if (n_given < 1 .or. n_given > max_steps) then
        call deck_error(ctx, "n", "must be from 1 to "//int_str(max_steps)//" (got "//int_str(n_given)// &
          "): the run would give no positions", error)
        return
      end if
      n = n_given
    else
      n_real = real(floor(360.0_wp / dphi * (1.0_wp + 1.0e-12_wp)), wp) + 1.0_wp
      if (n_real > real(max_steps, wp)) then
        call deck_error(ctx, "dphi", "too small: 360/dphi + 1 exceeds "//int_str(max_steps)//" steps", error)
        return
      end if
      n = nint(n_real)
    end if
  end subroutine steps_over_turn

end module kinetostat_deck
