!> Variables a deck assigns more than once ("omega1 = 20" on one line, "omega1 = 30" on
!> another): the namelist READ keeps the last value silently, which is rarely what was
!> meant; the CLI warns about each such variable.
module kinetostat_deck_repeats
  use kinetostat_text, only: int_str, lower, counted, without_blanks
  use kinetostat_deck, only: deck_source_t, deck_line_count, deck_line, assignment_starts
  implicit none
  private
  public :: deck_repeats

  !> One assignment: the variable as written (blanks dropped, lower case) and its line.
  type :: assigned_t
    !> The variable ("dyad(1)%l2").
    character(len=:), allocatable :: name
    !> Deck line (1..).
    integer :: line = 0
  end type assigned_t

  !> Longest deck line scanned, characters (a line of 10^6 values is data, not names: its
  !> assignments are found in its first characters).
  integer, parameter :: scan_width = 4096

contains

  !> One remark per variable assigned more than once: "omega1 is given twice (lines 6 and
  !> 9); the last value counts" (more: "3 times (lines 6, 9, 12)"). Empty when none. The
  !> lines `kinetostat balance` appends (from its first line whose comment names it) replace
  !> values on purpose and are not counted.
  pure function deck_repeats(source) result(remarks)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    character(len=:), allocatable :: remarks(:)
    type(assigned_t), allocatable :: seen(:)
    character(len=:), allocatable :: line, name, text
    integer, allocatable :: starts(:), lines(:)
    integer :: k, i, j, eq
    logical, allocatable :: reported(:)
    allocate (seen(0))
    do k = 1, deck_line_count(source)
      line = deck_line(source, k)
      if (len(line) > scan_width) line = line(1:scan_width)
      if (index(lower(line), "; kinetostat balance") > 0) exit
      starts = assignment_starts(line)
      do i = 1, size(starts)
        eq = index(line(starts(i):), "=")
        name = lower(line(starts(i):starts(i) + eq - 2))
        name = without_blanks(name)
        seen = [seen, assigned_t(name, k)]
      end do
    end do
    allocate (character(len=0) :: remarks(0))
    allocate (reported(size(seen)), source=.false.)
    do i = 1, size(seen)
      if (reported(i)) cycle
      allocate (lines(0))
      do j = i + 1, size(seen)
        if (seen(j)%name == seen(i)%name) then
          lines = [lines, seen(j)%line]
          reported(j) = .true.
        end if
      end do
      if (size(lines) > 0) then
        lines = [seen(i)%line, lines]
        text = seen(i)%name//" is given "//times(size(lines))//" (lines "//line_list(lines)// &
          "); the last value counts"
        remarks = [character(len=max(len(remarks), len(text))) :: remarks, text]
      end if
      deallocate (lines)
    end do
  contains
    pure function times(n) result(t)
      integer, intent(in) :: n
      character(len=:), allocatable :: t
      if (n == 2) then
        t = "twice"
      else
        t = counted(n, "time")
      end if
    end function times
    pure function line_list(ls) result(t)
      integer, intent(in) :: ls(:)
      character(len=:), allocatable :: t
      integer :: m
      t = int_str(ls(1))
      do m = 2, size(ls)
        if (m == size(ls)) then
          t = t//" and "//int_str(ls(m))
        else
          t = t//", "//int_str(ls(m))
        end if
      end do
    end function line_list
  end function deck_repeats


end module kinetostat_deck_repeats
