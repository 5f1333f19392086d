!> `&gear_geometry` decks: reading, validation and the commented template. One external spur
!> pair: module, teeth, the basic rack, and the shifts given (x1, x2), chosen (shift = 'auto')
!> or split from a prescribed working centre distance (a_w).
module kinetostat_gear_geometry_deck
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, number_str, lower
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, deck_context_t, unset_real, deck_source_t, &
    namelist_probe_t, deck_error, is_set, optional_default, deck_rules_t
  use kinetostat_gear_geometry, only: gear_pair_t, shift_sum_for_centre
  implicit none
  private
  public :: gear_geometry_deck_t, read_gear_geometry_deck, gear_geometry_template
  public :: shift_given, shift_auto, shift_from_x1, shift_from_x2, max_gear_teeth

  !> Shifts: x1 and x2 as given (0 when not given).
  integer, parameter :: shift_given = 1
  !> Shifts: chosen by the program (equal sliding; with a_w, the split of its sum).
  integer, parameter :: shift_auto = 2
  !> Shifts: x1 given, x2 = (x1 + x2 from a_w) - x1.
  integer, parameter :: shift_from_x1 = 3
  !> Shifts: x2 given, x1 = (x1 + x2 from a_w) - x2.
  integer, parameter :: shift_from_x2 = 4
  !> Largest number of teeth accepted.
  integer, parameter :: max_gear_teeth = 100000

  !> A validated `&gear_geometry` deck.
  type :: gear_geometry_deck_t
    !> Module, teeth and basic rack (angles in rad, lengths in mm).
    type(gear_pair_t) :: pair
    !> How the shifts are found: shift_given, shift_auto, shift_from_x1, shift_from_x2.
    integer :: rule = shift_given
    !> The shifts as given (shift_given), or the one given (shift_from_x1/x2).
    real(wp) :: x1 = 0.0_wp, x2 = 0.0_wp
    !> Whether a working centre distance is prescribed, and its value, mm.
    logical :: has_a_w = .false.
    real(wp) :: a_w = 0.0_wp
    !> With a_w: the sum x1 + x2 it requires.
    real(wp) :: x_sum = 0.0_wp
    !> Torque on gear 1 for the analysis deck (--format deck), N*m; whether given.
    logical :: has_m1 = .false.
    real(wp) :: m1 = 0.0_wp
  end type gear_geometry_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: gear_geometry_template(*) = [character(len=100) :: &
    "! kinetostat deck: geometry of an external spur pair of involute gears with profile shift.", &
    "! Module and diameters mm, angles deg. Give x1 and x2, or shift = 'auto' (equal largest", &
    "! specific sliding inside the blocking contour), or a_w with shift = 'auto' or one of x1, x2.", &
    "&gear_geometry", &
    "  m       = 3          ! mm, module, > 0", &
    "  z1      = 12         ! teeth of gear 1 (the pinion), >= 1", &
    "  z2      = 24         ! teeth of gear 2, >= 1", &
    "  x1      = 0.6        ! profile shift coefficient of gear 1 (default 0)", &
    "  x2      = 0.36       ! profile shift coefficient of gear 2 (default 0)", &
    "  ! shift = 'auto'     ! instead of x1, x2: the program chooses them", &
    "  ! a_w   = 56.5       ! mm, a prescribed working centre distance (x1 + x2 from it)", &
    "  alpha   = 20         ! deg, profile angle of the basic rack, in (0, 45); default 20", &
    "  ha_star = 1          ! addendum coefficient of the basic rack, > 0; default 1", &
    "  c_star  = 0.25       ! bottom clearance coefficient, >= 0; default 0.25", &
    "  sa_min_star = 0.25   ! least tip thickness in modules, >= 0; default 0.25", &
    "  ! m1    = 100        ! N*m, torque on gear 1: only for --format deck (the &gears deck)", &
    "/"]

contains

  !> Read and validate a `&gear_geometry` deck.
  subroutine read_gear_geometry_deck(source, deck, error)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(gear_geometry_deck_t), intent(out) :: deck
    !> Input error naming deck, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=text_bytes * text_chars) :: shift
    real(wp) :: m, z1, z2, x1, x2, a_w, alpha, ha_star, c_star, sa_min_star, m1
    integer :: iz1, iz2
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    type(error_t), allocatable :: why
    namelist /gear_geometry/ m, z1, z2, x1, x2, shift, a_w, alpha, ha_star, c_star, sa_min_star, m1

    call begin_group(source, "gear_geometry", ctx, error, rules)
    if (allocated(error)) return
    shift = " "
    m = unset_real; z1 = unset_real; z2 = unset_real; x1 = unset_real; x2 = unset_real
    a_w = unset_real; alpha = unset_real; ha_star = unset_real; c_star = unset_real
    sa_min_star = unset_real; m1 = unset_real
    read (source%records, nml=gear_geometry, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source))
      read (probe%records, nml=gear_geometry, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    call rules%require_all_set([character(len=2) :: "m", "z1", "z2"], [m, z1, z2])
    call rules%require_positive("m", m)
    call require_teeth(rules, "z1", z1, iz1)
    call require_teeth(rules, "z2", z2, iz2)
    alpha = optional_default(alpha, 20.0_wp)
    call rules%require_in("alpha", alpha, alpha > 0.0_wp .and. alpha < 45.0_wp, "(0, 45) deg")
    ha_star = optional_default(ha_star, 1.0_wp)
    call rules%require_positive("ha_star", ha_star)
    call rules%require_rule("ha_star", ha_star <= 10.0_wp, "must be <= 10 (got "//real_str(ha_star)//")")
    c_star = optional_default(c_star, 0.25_wp)
    call rules%require_nonnegative("c_star", c_star)
    call rules%require_rule("c_star", c_star <= 10.0_wp, "must be <= 10 (got "//real_str(c_star)//")")
    sa_min_star = optional_default(sa_min_star, 0.25_wp)
    call rules%require_nonnegative("sa_min_star", sa_min_star)
    call rules%require_rule("sa_min_star", sa_min_star <= 10.0_wp, "must be <= 10 (got "// &
      real_str(sa_min_star)//")")
    ! the shifts
    if (is_set(x1)) call require_shift(rules, "x1", x1)
    if (is_set(x2)) call require_shift(rules, "x2", x2)
    if (rules%failed(error)) return
    deck%pair%m = m
    deck%pair%z1 = iz1
    deck%pair%z2 = iz2
    deck%pair%alpha = alpha * deg_to_rad
    deck%pair%ha_star = ha_star
    deck%pair%c_star = c_star
    deck%pair%sa_min_star = sa_min_star

    select case (lower(trim(adjustl(shift))))
    case ("", "given")
      deck%rule = shift_given
    case ("auto")
      deck%rule = shift_auto
      call rules%require_rule("x1", .not. is_set(x1), "not with shift = 'auto' (the program chooses x1 and x2)")
      call rules%require_rule("x2", .not. is_set(x2), "not with shift = 'auto' (the program chooses x1 and x2)")
      if (rules%failed(error)) return
    case default
      call deck_error(ctx, "shift", "must be 'auto' or 'given' (got '"//trim(shift)//"')", error)
      return
    end select
    if (is_set(a_w)) then
      call rules%require_positive("a_w", a_w)
      if (rules%failed(error)) return
      call shift_sum_for_centre(deck%pair, a_w, deck%x_sum, why)
      if (allocated(why)) then
        call deck_error(ctx, "a_w", why%message, error)
        return
      end if
      call rules%require_rule("a_w", abs(deck%x_sum) <= 1000.0_wp, "requires x1 + x2 = "// &
        real_str(deck%x_sum)//", beyond any gear")
      if (rules%failed(error)) return
      deck%has_a_w = .true.
      deck%a_w = a_w
      if (deck%rule == shift_given) then
        if (is_set(x1) .and. is_set(x2)) then
          call deck_error(ctx, "a_w", "with x1 and x2 both given the centre distance follows from them: give "// &
            "one of x1, x2 (the other = x1 + x2 from a_w) or shift = 'auto'", error)
          return
        else if (is_set(x1)) then
          deck%rule = shift_from_x1
          deck%x1 = x1
        else if (is_set(x2)) then
          deck%rule = shift_from_x2
          deck%x2 = x2
        else
          call deck_error(ctx, "a_w", "gives x1 + x2 = "//real_str(deck%x_sum)//"; say how to split it: "// &
            "shift = 'auto' (equal largest specific sliding) or one of x1, x2", error)
          return
        end if
      end if
    else if (deck%rule == shift_given) then
      deck%x1 = optional_default(x1, 0.0_wp)
      deck%x2 = optional_default(x2, 0.0_wp)
    end if

    if (is_set(m1)) then
      call rules%require_set("m1", m1)
      if (rules%failed(error)) return
      deck%has_m1 = .true.
      deck%m1 = m1
    end if
  end subroutine read_gear_geometry_deck

  !> A shift coefficient: finite and within +-100 (beyond that no gear exists).
  subroutine require_shift(rules, name, x)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    real(wp), intent(in) :: x
    call rules%require_set(name, x)
    call rules%require_rule(name, abs(x) <= 100.0_wp, "must be within -100 .. 100 (got "//real_str(x)//")")
  end subroutine require_shift

  !> Teeth: a whole number from 1 to max_gear_teeth.
  subroutine require_teeth(rules, name, z, teeth)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    !> Deck value (an integer deck variable, read as a real).
    real(wp), intent(in) :: z
    integer, intent(out) :: teeth
    teeth = 0
    if (is_set(z)) call rules%require_rule(name, .not. z < 1.0_wp, "must be >= 1 teeth (got "//number_str(z)//")")
    call rules%require_whole(name, z, 1, max_gear_teeth, teeth)
  end subroutine require_teeth

end module kinetostat_gear_geometry_deck
