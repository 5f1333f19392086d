!> Variables of another deck kind: a stage a kind lacks (friction, a cycle of two turns, load
!> tables) is refused before the namelist READ with the reason and the way out, not with the
!> namelist's bare "unknown variable".
module kinetostat_deck_foreign
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str, lower
  use kinetostat_deck, only: deck_source_t, deck_line, deck_line_count, assignment_starts
  implicit none
  private
  public :: refuse_variables, refuse_translated_stages

contains

  !> The first assignment in the deck's group `group` to a variable whose name (before any
  !> '(' or '%') is one of `names` (lower case): the error "DECK:LINE: &group: VARIABLE:
  !> reason" (exit 2); none when the group assigns none of them.
  subroutine refuse_variables(source, group, names, reason, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Its group, lower case, without '&'.
    character(*), intent(in) :: group
    !> The names refused (blank-padded).
    character(*), intent(in) :: names(:)
    !> Why, and the way out.
    character(*), intent(in) :: reason
    type(error_t), allocatable, intent(out) :: error
    integer :: k, i, first, eq, cut
    integer, allocatable :: starts(:)
    character(len=:), allocatable :: line, assigned, base
    logical :: inside
    inside = .false.
    do k = 1, deck_line_count(source)
      line = deck_line(source, k)
      if (.not. inside) then
        first = verify(line, " "//achar(9))
        if (first == 0) cycle
        if (line(first:first) /= "&" .and. line(first:first) /= "$") cycle
        if (lower(line(first + 1:min(len(line), first + len(group)))) /= group) cycle
        inside = .true.
        line = line(first + 1 + len(group):)
      end if
      starts = assignment_starts(line)
      do i = 1, size(starts)
        eq = index(line(starts(i):), "=")
        if (eq == 0) cycle
        assigned = trim(line(starts(i):starts(i) + eq - 2))
        cut = scan(assigned, "(%")
        base = lower(assigned)
        if (cut > 0) base = lower(assigned(:cut - 1))
        base = trim(base)
        if (any(names == base)) then
          call fatal_error(error, exit_input, source%path//":"//int_str(k)//": &"//group//": "// &
            lower(assigned)//": "//reason)
          return
        end if
      end do
    end do
  end subroutine refuse_variables

  !> The stages a kind of fixed linkage (&pr3207, &pr3050, &sixbar) lacks and its `&linkage`
  !> translation has, refused with that way out, in this order: friction (crank_f, crank_r,
  !> dyad), a cycle of two turns (cycle: `cycle_reason`, by default the translation's), and
  !> loads and load tables (force, moment) beside the kind's own loads (`own_loads`: " but
  !> f5c", or empty).
  subroutine refuse_translated_stages(source, group, own_loads, error, cycle_reason)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Its group, lower case, without '&'.
    character(*), intent(in) :: group
    !> The kind's own loads, after "has no loads".
    character(*), intent(in) :: own_loads
    type(error_t), allocatable, intent(out) :: error
    !> Why `cycle` is refused, when not for the translation's sake.
    character(*), intent(in), optional :: cycle_reason
    character(*), parameter :: way_out = "(kinetostat convert DECK --to linkage)"
    call refuse_variables(source, group, [character(len=8) :: "crank_f", "crank_r", "dyad"], &
      "a &"//group//" deck has no friction; its &linkage translation has "//way_out, error)
    if (allocated(error)) return
    if (present(cycle_reason)) then
      call refuse_variables(source, group, [character(len=8) :: "cycle"], cycle_reason, error)
    else
      call refuse_variables(source, group, [character(len=8) :: "cycle"], "a &"//group//" deck's cycle is one "// &
        "turn; a cycle of two turns runs on its &linkage translation "//way_out, error)
    end if
    if (allocated(error)) return
    call refuse_variables(source, group, [character(len=8) :: "force", "moment"], "a &"//group//" deck has no "// &
      "loads"//own_loads//", and no load tables; its &linkage translation has them "//way_out, error)
  end subroutine refuse_translated_stages

end module kinetostat_deck_foreign
