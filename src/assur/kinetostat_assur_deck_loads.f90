!> `&assur` decks: reading the loads' schedules (constants, windows, step_values columns,
!> tables over a link's position) and finding the links a variable names.
module kinetostat_assur_deck_loads
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str, number_str
  use kinetostat_deck, only: deck_context_t, max_deck_array, deck_error, is_set, require_set, require_rule, &
    optional_default, require_whole, deck_rules_t
  use kinetostat_vec2, only: magnitude
  use kinetostat_assur, only: output_pair_of
  use kinetostat_assur_deck_types, only: schedule_in_t, load_constant, load_window, load_column, load_table, &
    load_schedule_t, assur_deck_t, resist_none
  use kinetostat_load_table, only: read_table_points
  use kinetostat_assur_steps, only: table_position, assur_phi1_deg
  implicit none
  private
  public :: read_load, read_table, find_link, read_schedule

contains

  !> The schedule of force or moment `name`: a table over a link's position (read_table), or
  !> a constant, window or step_values column (read_schedule; `over` only goes with a table).
  subroutine read_load(ctx, name, table, over, sched, ids, deck, n_values, resist, link, load, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: name
    !> The table as read.
    real(wp), intent(in) :: table(:)
    !> Link id of the table's abscissa, or unset.
    real(wp), intent(in) :: over
    !> value, idle, phi_on, phi_off, column as read.
    type(schedule_in_t), intent(in) :: sched
    !> Link ids by internal index.
    integer, intent(in) :: ids(0:)
    !> The deck (mechanism and crank angles).
    type(assur_deck_t), intent(in) :: deck
    !> Number of step_values given.
    integer, intent(in) :: n_values
    !> resist_force or resist_moment for a technological resistance (resist = .true.: its
    !> size checked by resist_size), else resist_none.
    integer, intent(in) :: resist
    !> Internal index of the loaded link.
    integer, intent(in) :: link
    !> The load's schedule.
    type(load_schedule_t), intent(out) :: load
    type(error_t), allocatable, intent(out) :: error
    type(schedule_in_t) :: s
    if (is_set(table(1))) then
      call read_table(ctx, name, table, over, [sched%value, sched%idle, sched%phi_on, sched%phi_off, sched%column], &
                      ids, deck, load, error)
    else
      call require_rule(ctx, name//"over", .not. is_set(over), "only used with table", error)
      if (allocated(error)) return
      s = sched
      call read_schedule(ctx, name, s, deck%n, n_values, load, error)
    end if
    if (allocated(error) .or. resist == resist_none) return
    call resist_size(ctx, name, sched%value, sched%idle, error); if (allocated(error)) return
    load%resist = resist
    load%resist_link = link
  end subroutine read_load

  !> Per-step values of a load given as a table of (position, value) pairs over the position
  !> of link `over` (default: the output link): its angle in deg, taken modulo 360 into
  !> [x1, x1 + 360), or a slider's stroke on its frame guide in m; linear interpolation,
  !> positions strictly increasing, every step's position inside the table.
  subroutine read_table(ctx, name, table, over, others, ids, deck, load, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: name
    !> The table as read.
    real(wp), intent(in) :: table(:)
    !> Link id of the abscissa, or unset.
    real(wp), intent(in) :: over
    !> value, idle, phi_on, phi_off, column as read (must be unset).
    real(wp), intent(in) :: others(:)
    !> Link ids by internal index.
    integer, intent(in) :: ids(0:)
    !> The deck (mechanism and crank angles).
    type(assur_deck_t), intent(in) :: deck
    !> The load's schedule (a table; its values per step by assur_load_value).
    type(load_schedule_t), intent(out) :: load
    type(error_t), allocatable, intent(out) :: error
    !> Abscissa link's position at a step, deg or m.
    real(wp) :: q
    !> Tolerance of the range check, deg or m.
    real(wp) :: tol
    !> Whether the step's kinematics succeeded.
    logical :: ok
    integer :: np, i, k
    character(len=:), allocatable :: unit
    load%kind = load_table
    call require_rule(ctx, name//"table", .not. any(is_set(others)), &
      "give either table (values over a link's position) or value [idle, phi_on, phi_off] or column", error)
    if (allocated(error)) return
    call read_table_points(ctx, name//"table", table, load%x, load%v, error); if (allocated(error)) return
    np = size(load%x)
    i = deck%mech%output_link
    if (is_set(over)) then
      call find_link(ctx, name//"over", over, ids, .false., i, error); if (allocated(error)) return
    end if
    load%link = i
    load%pair = output_pair_of(deck%mech, i)
    unit = " deg"
    if (load%pair /= 0) unit = " m"
    associate (x => load%x)
      tol = 1.0e-9_wp * max(x(np) - x(1), abs(x(1)), abs(x(np)), 1.0e-300_wp)
      do k = 1, deck%n
        call table_position(deck, load, k, q, ok)
        if (.not. ok) cycle ! reported by the solution with the step
        if (q < x(1) - tol .or. q > x(np) + tol) then
          call deck_error(ctx, name//"table", "at step "//int_str(k)//" (phi1 = "//real_str(assur_phi1_deg(deck, k))// &
            " deg) link "//int_str(ids(i))//" is at "//real_str(q)//unit//", outside the table ["// &
            real_str(x(1))//", "//real_str(x(np))//"]"//unit, error)
          return
        end if
      end do
    end associate
  end subroutine read_table

  !> A technological resistance's constant size: `value` and `idle` (when given) >= 0 (its
  !> sign comes from the motion; a table's or column's values are taken by magnitude).
  subroutine resist_size(ctx, name, value, idle, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "moment(1)%".
    character(*), intent(in) :: name
    !> value and idle as read (or unset).
    real(wp), intent(in) :: value, idle
    type(error_t), allocatable, intent(out) :: error
    call require_rule(ctx, name//"value", .not. (is_set(value) .and. value < 0.0_wp), &
      "must be >= 0 with resist = .true. (the size of the resistance; the motion gives its sign)", error)
    if (allocated(error)) return
    call require_rule(ctx, name//"idle", .not. (is_set(idle) .and. idle < 0.0_wp), &
      "must be >= 0 with resist = .true. (the size of the resistance; the motion gives its sign)", error)
  end subroutine resist_size

  !> The internal index of a link id among `ids(0:)`: a moving link (crank or dyad link), or
  !> also the frame when `allow_frame`.
  subroutine find_link(ctx, name, id_in, ids, allow_frame, index, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    !> Link number as given (an integer deck variable, read as a real).
    real(wp), intent(in) :: id_in
    integer, intent(in) :: ids(0:)
    logical, intent(in) :: allow_frame
    integer, intent(out) :: index
    type(error_t), allocatable, intent(out) :: error
    integer :: i, id
    index = -1
    if (.not. is_set(id_in)) then
      call deck_error(ctx, name, "missing (required link number)", error)
      return
    end if
    call require_whole(ctx, name, id_in, 0, huge(1), id, error); if (allocated(error)) return
    do i = 0, ubound(ids, 1)
      if (ids(i) == id) index = i
    end do
    if (index < 0 .or. (index == 0 .and. .not. allow_frame)) then
      if (allow_frame) then
        call deck_error(ctx, name, "link "//int_str(id)//" is not the frame, the crank or a link "// &
          "of an earlier dyad (a dyad may only hang on links defined before it)", error)
      else
        call deck_error(ctx, name, "link "//int_str(id)//" is not a moving link (crank or dyad link)", error)
      end if
    end if
  end subroutine find_link

  !> A load's schedule (constant, window, or a step_values column) from the deck.
  subroutine read_schedule(ctx, name, s, n, n_values, load, error)
    type(deck_context_t), intent(in) :: ctx
    !> Prefix, e.g. "force(1)%".
    character(*), intent(in) :: name
    type(schedule_in_t), intent(inout) :: s
    !> Number of steps.
    integer, intent(in) :: n
    !> Number of step_values given.
    integer, intent(in) :: n_values
    !> The validated schedule (its value at step k: assur_load_value).
    type(load_schedule_t), intent(out) :: load
    type(error_t), allocatable, intent(out) :: error
    integer :: column
    !> The checks of a column schedule.
    type(deck_rules_t) :: rules
    if (is_set(s%column)) then
      rules = deck_rules_t(ctx)
      call rules%require_rule(name//"column", .not. any(is_set([s%value, s%idle, s%phi_on, s%phi_off])), &
        "give either column (per-step values) or value [idle, phi_on, phi_off], not both")
      call rules%require_whole(name//"column", s%column, 1, max_deck_array, column)
      ! column*n in real arithmetic: both may be up to a million
      call rules%require_rule(name//"column", real(column, wp) * real(n, wp) <= real(n_values, wp), &
        "step_values has "//int_str(n_values)//" values; column "//int_str(column)//" needs "// &
        number_str(real(column, wp) * real(n, wp))//" (n = "//int_str(n)//" per column)")
      if (rules%failed(error)) return
      load%kind = load_column
      load%offset = (column - 1) * n
      return
    end if
    call require_set(ctx, name//"value", s%value, error); if (allocated(error)) return
    if (is_set(s%phi_on) .or. is_set(s%phi_off)) then
      call require_set(ctx, name//"phi_on", s%phi_on, error); if (allocated(error)) return
      call require_set(ctx, name//"phi_off", s%phi_off, error); if (allocated(error)) return
      call require_rule(ctx, name//"phi_off", s%phi_off >= s%phi_on, "must be >= phi_on ("// &
        real_str(s%phi_on)//"), got "//real_str(s%phi_off), error)
      if (allocated(error)) return
      s%idle = optional_default(s%idle, 0.0_wp)
      call require_set(ctx, name//"idle", s%idle, error); if (allocated(error)) return
      load = load_schedule_t(kind=load_window, value=s%value, idle=s%idle, phi_on=s%phi_on, phi_off=s%phi_off)
    else
      call require_rule(ctx, name//"idle", .not. is_set(s%idle), "only used with phi_on, phi_off", error)
      if (allocated(error)) return
      load = load_schedule_t(kind=load_constant, value=s%value)
    end if
  end subroutine read_schedule

end module kinetostat_assur_deck_loads
