!> Variables of another deck kind: a stage a kind lacks (friction, a cycle of two turns, load
!> tables) is refused before the namelist READ with the reason and the way out, not with the
!> namelist's bare "unknown variable".
module kinetostat_deck_foreign
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str, lower
  use kinetostat_deck, only: deck_source_t, deck_line, deck_line_count, assignment_starts
  implicit none
  private
  public :: refuse_variables

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

end module kinetostat_deck_foreign
