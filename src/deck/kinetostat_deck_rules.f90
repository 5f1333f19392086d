!> Validation rules of a deck's values: "not set" (a NaN sentinel no deck can type), the
!> required, positive, whole, per-step checks, each a message naming the file, the group,
!> the variable and the reason; and a validator (deck_rules_t) whose checks do nothing once
!> one has failed, so that a section of a reader runs its checks and looks at the result
!> once.
module kinetostat_deck_rules
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: real_str, int_str, int64_str, number_str, char_count, lower
  use kinetostat_deck_source, only: deck_context_t
  implicit none
  private
  public :: unset_real, unset_bits, max_steps
  public :: deck_error, require_all_set, values_out_of_memory
  public :: is_set, require_set, require_positive, require_nonnegative, require_rule, require_per_step
  public :: is_whole_in, require_whole, require_chars
  public :: optional_default, count_values, steps_over_turn, deck_rules_t
  public :: rule_finite, rule_positive, rule_nonnegative
  public :: angle_steps_t, step_angle_deg

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
  !> Largest number of steps a run may have.
  integer, parameter :: max_steps = 1000000
  !> The value rules of require_value and deck_rules_t%require_each: a required real that
  !> is finite; also > 0; also >= 0.
  integer, parameter :: rule_finite = 0, rule_positive = 1, rule_nonnegative = 2

  !> The input angles of a run's steps (the crank's; PR 3050's rocker's), phi_start + (k -
  !> 1)*dphi for k = 1..n, computed, not stored (a kind's validated deck extends it; the
  !> angle of step k is step_angle_deg).
  type :: angle_steps_t
    !> First angle, deg.
    real(wp) :: phi_start = 0.0_wp
    !> Step, deg.
    real(wp) :: dphi = 0.0_wp
    !> Number of steps.
    integer :: n = 0
  end type angle_steps_t

  !> A validator of one section of a reader: the deck and group its messages name, and the
  !> first failure. Its checks are the rules below and do nothing once one has failed, so a
  !> section calls them in order and asks once, at its end, whether one failed (a reader's
  !> begin_group gives it the deck and group):
  !>     call rules%require_positive("l_ab", deck%l_ab)
  !>     call rules%require_whole("n", deck%n, 1, max_steps, n)
  !>     if (rules%failed(error)) return
  !> The message is the first failing check's, as with the rules called one by one.
  type :: deck_rules_t
    !> Deck and group.
    type(deck_context_t) :: ctx
    !> The first failure (unallocated while every check passed).
    type(error_t), allocatable :: error
  contains
    procedure :: require_set => rules_set
    procedure :: require_positive => rules_positive
    procedure :: require_nonnegative => rules_nonnegative
    procedure :: require_each => rules_each
    procedure :: require_rule => rules_rule
    procedure :: require_in => rules_in
    procedure :: require_whole => rules_whole
    procedure :: require_chars => rules_chars
    procedure :: require_choice => rules_choice
    procedure :: require_per_step => rules_per_step
    procedure :: require_all_set => rules_all_set
    procedure :: count_values => rules_count_values
    procedure :: count_texts => rules_count_texts
    procedure :: crank_steps => rules_crank_steps
    procedure :: ok => rules_ok
    procedure :: failed => rules_failed
    procedure :: take => rules_take
  end type deck_rules_t

contains

  !> "<deck>: &<group>: missing required variables: a, b, c".
  pure subroutine require_all_set(ctx, names, values, error)
    !> Deck and group.
    type(deck_context_t), intent(in) :: ctx
    !> Names of the required variables (trailing blanks dropped).
    character(*), intent(in) :: names(:)
    !> Their values as read (unset_real when not set).
    real(wp), intent(in) :: values(:)
    !> The input error (none when all are set).
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: missing
    integer :: i, count
    missing = ""
    count = 0
    do i = 1, size(names)
      if (is_set(values(i))) cycle
      count = count + 1
      if (count > 1) missing = missing//", "
      missing = missing//trim(names(i))
    end do
    if (count == 1) then
      call fatal_error(error, exit_input, ctx%path//": &"//ctx%group//": "//missing//": missing (required variable)")
    else if (count > 1) then
      call fatal_error(error, exit_input, ctx%path//": &"//ctx%group//": missing required variables: "//missing)
    end if
  end subroutine require_all_set

  !> An input error about one variable: "<deck>: &<group>: <name>: <reason>".
  !> The error of a deck's per-step arrays that could not be allocated (exit 2): "deck.nml:
  !> &group: out of memory: no room for the values of omega3, eps3 (16000000 bytes)".
  pure subroutine values_out_of_memory(ctx, names, counts, error)
    type(deck_context_t), intent(in) :: ctx
    !> The arrays, comma-separated.
    character(*), intent(in) :: names
    !> Their sizes, values.
    integer, intent(in) :: counts(:)
    type(error_t), allocatable, intent(out) :: error
    call fatal_error(error, exit_input, ctx%path//": &"//ctx%group//": out of memory: no room for the values of "// &
      names//" ("//int64_str(8_int64 * sum(int(counts, int64)))//" bytes)")
  end subroutine values_out_of_memory

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
    call require_value(ctx, name, x, rule_finite, error)
  end subroutine require_set

  !> Required real, finite and > 0.
  subroutine require_positive(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    call require_value(ctx, name, x, rule_positive, error)
  end subroutine require_positive

  !> Required real, finite and >= 0.
  subroutine require_nonnegative(ctx, name, x, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    type(error_t), allocatable, intent(out) :: error
    call require_value(ctx, name, x, rule_nonnegative, error)
  end subroutine require_nonnegative

  !> A required real under one of the value rules: set ("missing (required variable)"),
  !> finite ("must be a finite number (got X)"), and for rule_positive > 0, for
  !> rule_nonnegative >= 0 ("must be > 0 (got X)", "must be >= 0 (got X)").
  subroutine require_value(ctx, name, x, rule, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    !> rule_finite, rule_positive or rule_nonnegative.
    integer, intent(in) :: rule
    type(error_t), allocatable, intent(out) :: error
    if (.not. is_set(x)) then
      call deck_error(ctx, name, "missing (required variable)", error)
    else if (.not. ieee_is_finite(x)) then
      call deck_error(ctx, name, "must be a finite number (got "//real_str(x)//")", error)
    else if (rule == rule_positive .and. .not. x > 0.0_wp) then
      call deck_error(ctx, name, "must be > 0 (got "//real_str(x)//")", error)
    else if (rule == rule_nonnegative .and. .not. x >= 0.0_wp) then
      call deck_error(ctx, name, "must be >= 0 (got "//real_str(x)//")", error)
    end if
  end subroutine require_value

  !> A rule between variables: when `ok` is false, report `reason` against `name`.
  pure subroutine require_rule(ctx, name, ok, reason, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    logical, intent(in) :: ok
    character(*), intent(in) :: reason
    type(error_t), allocatable, intent(out) :: error
    if (.not. ok) call deck_error(ctx, name, reason, error)
  end subroutine require_rule

  !> A text of at most `most` characters (UTF-8 characters, not bytes): else "longer than
  !> 80 characters (it has 95)".
  pure subroutine require_chars(ctx, name, text, most, error)
    type(deck_context_t), intent(in) :: ctx
    !> The text's variable.
    character(*), intent(in) :: name
    !> The text (trailing blanks do not count).
    character(*), intent(in) :: text
    !> Most characters.
    integer, intent(in) :: most
    type(error_t), allocatable, intent(out) :: error
    integer :: n
    n = char_count(trim(text))
    if (n > most) call deck_error(ctx, name, "longer than "//int_str(most)//" characters (it has "// &
      int_str(n)//")", error)
  end subroutine require_chars

  !> A per-step list `name` of `count` values must have one value per step (`n`).
  pure subroutine require_per_step(ctx, name, count, n, error)
    type(deck_context_t), intent(in) :: ctx
    !> The list's variable name.
    character(*), intent(in) :: name
    !> How many values the deck gave.
    integer, intent(in) :: count
    !> Number of steps.
    integer, intent(in) :: n
    type(error_t), allocatable, intent(out) :: error
    if (count /= n) call deck_error(ctx, name, "expected "//int_str(n)//" values (one per step), got "// &
                                    int_str(count), error)
  end subroutine require_per_step

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

  !> Whether no check of the section has failed so far.
  pure logical function rules_ok(self)
    class(deck_rules_t), intent(in) :: self
    rules_ok = .not. allocated(self%error)
  end function rules_ok

  !> Whether a check failed; then `error` is its error (and the validator is clear again).
  logical function rules_failed(self, error)
    class(deck_rules_t), intent(inout) :: self
    !> The first failure.
    type(error_t), allocatable, intent(out) :: error
    rules_failed = allocated(self%error)
    if (rules_failed) call move_alloc(self%error, error)
  end function rules_failed

  !> The first failure into `error` (unallocated when every check passed), for a section
  !> that ends there; the validator is clear again.
  subroutine rules_take(self, error)
    class(deck_rules_t), intent(inout) :: self
    type(error_t), allocatable, intent(out) :: error
    if (allocated(self%error)) call move_alloc(self%error, error)
  end subroutine rules_take

  !> require_set, once no check has failed.
  subroutine rules_set(self, name, x)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    if (.not. allocated(self%error)) call require_value(self%ctx, name, x, rule_finite, self%error)
  end subroutine rules_set

  !> require_positive, once no check has failed.
  subroutine rules_positive(self, name, x)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    if (.not. allocated(self%error)) call require_value(self%ctx, name, x, rule_positive, self%error)
  end subroutine rules_positive

  !> require_nonnegative, once no check has failed.
  subroutine rules_nonnegative(self, name, x)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    if (.not. allocated(self%error)) call require_value(self%ctx, name, x, rule_nonnegative, self%error)
  end subroutine rules_nonnegative

  !> A table of variables under one value rule, checked in order (the first failure is
  !> kept): `call rules%require_each(rule_nonnegative, [character(2) :: "m1", "m2"], [m1, m2])`.
  subroutine rules_each(self, rule, names, values)
    class(deck_rules_t), intent(inout) :: self
    !> rule_finite, rule_positive or rule_nonnegative.
    integer, intent(in) :: rule
    !> The variables' names (trailing blanks dropped).
    character(*), intent(in) :: names(:)
    !> Their values as read.
    real(wp), intent(in) :: values(:)
    integer :: i
    do i = 1, size(names)
      if (allocated(self%error)) return
      call require_value(self%ctx, trim(names(i)), values(i), rule, self%error)
    end do
  end subroutine rules_each

  !> require_rule, once no check has failed.
  subroutine rules_rule(self, name, ok, reason)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    logical, intent(in) :: ok
    character(*), intent(in) :: reason
    if (.not. allocated(self%error)) call require_rule(self%ctx, name, ok, reason, self%error)
  end subroutine rules_rule

  !> A required real in a range, once no check has failed: set and finite, then `inside`
  !> ("must be in (0, 45) deg (got 50)" for the range "(0, 45) deg").
  subroutine rules_in(self, name, x, inside, range)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    !> Whether `x` lies in the range.
    logical, intent(in) :: inside
    !> The range as the message names it.
    character(*), intent(in) :: range
    call self%require_set(name, x)
    call self%require_rule(name, inside, "must be in "//range//" (got "//real_str(x)//")")
  end subroutine rules_in

  !> require_whole, once no check has failed (`value` is `lo` when one had).
  subroutine rules_whole(self, name, x, lo, hi, value)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    integer, intent(in) :: lo, hi
    integer, intent(out) :: value
    value = lo
    if (.not. allocated(self%error)) call require_whole(self%ctx, name, x, lo, hi, value, self%error)
  end subroutine rules_whole

  !> require_chars, once no check has failed.
  subroutine rules_chars(self, name, text, most)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    character(*), intent(in) :: text
    integer, intent(in) :: most
    if (.not. allocated(self%error)) call require_chars(self%ctx, name, text, most, self%error)
  end subroutine rules_chars

  !> A keyword variable, once no check has failed: its text (blanks around it and case
  !> ignored) one of `names`, `code` its index there; a blank text means names(default), or
  !> without `default` is "missing: give 'a', 'b' or 'c'"; any other text "must be 'a', 'b'
  !> or 'c' (got 'd')". `code` is 0 when a check failed.
  subroutine rules_choice(self, name, text, names, code, default)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    !> The text as the deck gives it.
    character(*), intent(in) :: text
    !> The words accepted, in the order the message lists them (trailing blanks dropped).
    character(*), intent(in) :: names(:)
    integer, intent(out) :: code
    !> The index of the word a blank text stands for.
    integer, intent(in), optional :: default
    character(len=:), allocatable :: choices
    integer :: i
    code = 0
    if (allocated(self%error)) return
    choices = "'"//trim(names(1))//"'"
    do i = 2, size(names)
      if (i < size(names)) then
        choices = choices//", '"//trim(names(i))//"'"
      else
        choices = choices//" or '"//trim(names(i))//"'"
      end if
    end do
    if (len_trim(text) == 0 .and. present(default)) then
      code = default
    else if (len_trim(text) == 0) then
      call self%require_rule(name, .false., "missing: give "//choices)
    else
      code = findloc(names, lower(trim(adjustl(text))), dim=1)
      call self%require_rule(name, code /= 0, "must be "//choices//" (got '"//trim(text)//"')")
    end if
  end subroutine rules_choice

  !> require_per_step, once no check has failed.
  subroutine rules_per_step(self, name, count, n)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    integer, intent(in) :: count
    integer, intent(in) :: n
    if (.not. allocated(self%error)) call require_per_step(self%ctx, name, count, n, self%error)
  end subroutine rules_per_step

  !> require_all_set, once no check has failed.
  subroutine rules_all_set(self, names, values)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: names(:)
    real(wp), intent(in) :: values(:)
    if (.not. allocated(self%error)) call require_all_set(self%ctx, names, values, self%error)
  end subroutine rules_all_set

  !> count_values, once no check has failed (`count` is 0 when one had).
  subroutine rules_count_values(self, name, values, count)
    class(deck_rules_t), intent(inout) :: self
    character(*), intent(in) :: name
    real(wp), intent(in) :: values(:)
    integer, intent(out) :: count
    count = 0
    if (.not. allocated(self%error)) call count_values(self%ctx, name, values, count, self%error)
  end subroutine rules_count_values

  !> Number of words a deck gave for an array of texts (one per stage, segment, ...), once no
  !> check has failed: the leading non-blank entries, at least one ("<name>: missing:
  !> <missing>") and no non-blank entry after them (no gaps). `count` is 0 when a check failed.
  subroutine rules_count_texts(self, name, texts, missing, count)
    class(deck_rules_t), intent(inout) :: self
    !> The array's name.
    character(*), intent(in) :: name
    !> Its entries as read (blank when not given).
    character(*), intent(in) :: texts(:)
    !> What to give, for the message when none is given.
    character(*), intent(in) :: missing
    !> How many were given.
    integer, intent(out) :: count
    integer :: i
    count = 0
    if (allocated(self%error)) return
    do i = 1, size(texts)
      if (len_trim(texts(i)) == 0) exit
      count = i
    end do
    if (count == 0) then
      call deck_error(self%ctx, name, "missing: "//missing, self%error)
    else if (any(len_trim(texts(count + 1:)) > 0)) then
      call deck_error(self%ctx, name, "values must be given without gaps (element "//int_str(count + 1)// &
        " is missing)", self%error)
    end if
    if (allocated(self%error)) count = 0
  end subroutine rules_count_texts

  !> The crank angles of a run, once no check has failed: phi_start (deg, optional:
  !> default 0) and the number of steps from dphi and n (steps_over_turn).
  subroutine rules_crank_steps(self, phi_start, dphi, n_given, n)
    class(deck_rules_t), intent(inout) :: self
    !> First crank angle, deg, as read (its default when unset).
    real(wp), intent(inout) :: phi_start
    !> Crank step, deg (validated > 0 here).
    real(wp), intent(in) :: dphi
    !> `n` from the deck (a real holding a whole number), or unset_real.
    real(wp), intent(in) :: n_given
    !> Number of steps (0 when a check failed).
    integer, intent(out) :: n
    n = 0
    phi_start = optional_default(phi_start, 0.0_wp)
    call self%require_set("phi_start", phi_start)
    if (.not. allocated(self%error)) call steps_over_turn(self%ctx, dphi, n_given, n, self%error)
  end subroutine rules_crank_steps

  !> Input angle of step k, deg: phi_start + (k - 1)*dphi.
  pure real(wp) function step_angle_deg(steps, k) result(phi)
    !> The validated deck's steps.
    class(angle_steps_t), intent(in) :: steps
    !> Step number, 1..n.
    integer, intent(in) :: k
    phi = steps%phi_start + real(k - 1, wp) * steps%dphi
  end function step_angle_deg

end module kinetostat_deck_rules
