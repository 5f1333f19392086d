!> The structural analysis of any linkage from its model (`kinetostat structure` of a deck
!> whose mechanism has no analysis of its own: PR 3207, PR 3050, the T.FTN six-bar, the
!> generic engine): the moving links n and the lower pairs p5 of its topology (kinetostat_sketch:
!> a turning pair where links, or a link and the frame's pivot, share a joint; a sliding pair
!> where a link slides on a guide), W = 3n - 2p5, the units of plan_groups (the one place the
!> plans take their groups from) with each dyad's kind (outer pair of its first link, inner
!> pair, outer pair of its second: RRR, RRP, RPR, PRP, RPP), the structure formula and the
!> class - the lines `kinetostat structure` prints for a `&linkage` deck.
module kinetostat_plans_structure
  use kinetostat_text, only: int_str
  use kinetostat_labels, only: lang_ru, echo_name
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t
  use kinetostat_plans_base, only: plan_group_t, slide_t, slides_of, slide_is_pair, lists, sliding_on
  use kinetostat_plans_groups, only: plan_groups
  implicit none
  private
  public :: structure_lines_of, roman, unit_description

  !> Length of a line.
  integer, parameter :: line_len = 160

contains

  !> The structural analysis of the mechanism drawn at row k (its topology and units are the
  !> same at every row), as the lines of `kinetostat structure` (without indentation).
  pure subroutine structure_lines_of(topo, drawing, table, k, lang, lines)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(step_table_t), intent(in) :: table
    !> Row of the table.
    integer, intent(in) :: k
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=line_len), allocatable, intent(out) :: lines(:)
    type(slide_t), allocatable :: slides(:)
    type(plan_group_t), allocatable :: groups(:)
    !> The pairs: links a and b (0 the frame), kind 'R' or 'P'.
    integer, allocatable :: pa(:), pb(:)
    character(len=1), allocatable :: pk(:)
    character(len=:), allocatable :: driver, formula
    integer, allocatable :: bodies(:)
    integer :: n, p5, g, i, ip, s, top
    driver = ""
    if (allocated(table%driver)) driver = table%driver
    call slides_of(topo, drawing, table, k, slides)
    call plan_groups(topo, drawing, table, slides, driver, groups)
    n = size(topo%links)
    allocate (pa(0), pb(0), pk(0))
    ! turning pairs: the bodies at a joint (the links that list it and do not slide there, the
    ! frame at a pivot), b of them joined by b - 1 pairs
    do ip = 1, size(drawing%points)
      associate (pname => drawing%points(ip)%name)
        bodies = [integer ::]
        do i = 1, n
          if (lists(topo, i, trim(pname)) .and. .not. sliding_on(topo, i, trim(pname))) bodies = [bodies, i]
        end do
        if (allocated(topo%pivots)) then
          if (any(topo%pivots == pname)) bodies = [0, bodies]
        end if
        do i = 2, size(bodies)
          pa = [pa, bodies(1)]
          pb = [pb, bodies(i)]
          pk = [character(len=1) :: pk, "R"]
        end do
      end associate
    end do
    ! sliding pairs (a block on a guide may be found from both: one pair)
    do s = 1, size(slides)
      if (.not. slide_is_pair(topo, slides, s)) cycle
      if (any(pk == "P" .and. ((pa == slides(s)%m .and. pb == slides(s)%g) .or. &
                               (pa == slides(s)%g .and. pb == slides(s)%m)))) cycle
      pa = [pa, slides(s)%m]
      pb = [pb, slides(s)%g]
      pk = [character(len=1) :: pk, "P"]
    end do
    p5 = size(pa)
    allocate (lines(0))
    call push("STRUCTURAL ANALYSIS")
    call push("MOVING LINKS n = "//int_str(n)//", LOWER PAIRS p5 = "//int_str(p5)//", HIGHER PAIRS p4 = 0")
    call push("W = 3n - 2p5 - p4 = 3 x "//int_str(n)//" - 2 x "//int_str(p5)//" - 0 = "//int_str(3 * n - 2 * p5)// &
              " = NUMBER OF DRIVES")
    top = 1
    formula = ""
    do g = 1, size(groups)
      associate (gr => groups(g))
        top = max(top, gr%class)
        if (gr%class == 0) top = 99
        call push(gr%label//"  "//unit_description(gr%class, size(gr%links), dyad_kind(gr%links)))
        if (g > 1) formula = formula//" -> "
        formula = formula//gr%label
      end associate
    end do
    call push("STRUCTURE FORMULA: "//formula)
    call push("CLASS OF THE MECHANISM: "//roman(merge(top, 0, top < 99)))
    if (lang /= lang_ru) return
    do i = 1, size(lines)
      lines(i) = echo_name(trim(lines(i)), lang_ru)
    end do
  contains
    !> Appends a line.
    pure subroutine push(text)
      character(*), intent(in) :: text
      character(len=line_len), allocatable :: more(:)
      allocate (more(size(lines) + 1))
      more(1:size(lines)) = lines
      more(size(more)) = text
      call move_alloc(more, lines)
    end subroutine push

    !> The kind of the dyad of links d(1), d(2): its first link's outer pair, the inner pair,
    !> the second link's outer pair, written as the course names the five kinds (a reversed
    !> RRP is RRP).
    pure function dyad_kind(d) result(kind)
      integer, intent(in) :: d(:)
      character(len=:), allocatable :: kind
      character(len=3) :: reversed
      kind = "?"
      if (size(d) /= 2) return
      kind = pair_kind(d(1), d(2), .false.)//pair_kind(d(1), d(2), .true.)//pair_kind(d(2), d(1), .false.)
      reversed = kind(3:3)//kind(2:2)//kind(1:1)
      if (kind == "PRR" .or. kind == "PPR") kind = reversed
    end function dyad_kind

    !> The kind of the pair of link a with link b (`inner`), or with a link outside the dyad
    !> (a, b), "?" when there is none.
    pure function pair_kind(a, b, inner) result(c)
      integer, intent(in) :: a, b
      logical, intent(in) :: inner
      character(len=1) :: c
      integer :: q, other
      c = "?"
      do q = 1, size(pa)
        if (pa(q) == a) then
          other = pb(q)
        else if (pb(q) == a) then
          other = pa(q)
        else
          cycle
        end if
        if ((other == b) .eqv. inner) then
          c = pk(q)
          return
        end if
      end do
    end function pair_kind
  end subroutine structure_lines_of

  !> What a unit of the structure is, in the words of `kinetostat structure`: the input
  !> link(s) (class I), a dyad of `kind` (class II), a group of class III of order 3 (four
  !> links) or 4 (six links), a closed four-link contour (class IV), else a group of
  !> `n_links` links whose class was not found.
  pure function unit_description(class, n_links, kind) result(line)
    !> The unit's class (0: not found).
    integer, intent(in) :: class
    !> Number of its links.
    integer, intent(in) :: n_links
    !> A dyad's kind (RRR, RRP, RPR, PRP, RPP).
    character(*), intent(in) :: kind
    character(len=:), allocatable :: line
    select case (class)
    case (1)
      line = "INPUT LINK(S) (MECHANISM OF CLASS I)"
    case (2)
      line = "DYAD (GROUP OF CLASS II, ORDER 2), KIND "//kind
    case (3)
      if (n_links == 6) then
        line = "GROUP OF CLASS III, ORDER 4 (TWO TERNARY BASE LINKS AND FOUR BINARY LINKS)"
      else
        line = "GROUP OF CLASS III, ORDER 3 (A TERNARY BASE LINK AND THREE BINARY LINKS)"
      end if
    case (4)
      line = "GROUP OF CLASS IV, ORDER 2 (A CLOSED FOUR-LINK CONTOUR)"
    case default
      line = "GROUP OF "//int_str(n_links)//" LINKS (CLASS NOT DETERMINED)"
    end select
  end function unit_description

  !> A class in Roman numerals ("?" outside 1..8; the structure formula's I, II, III).
  pure function roman(class) result(text)
    integer, intent(in) :: class
    character(len=:), allocatable :: text
    character(len=4), parameter :: numerals(8) = [character(len=4) :: "I", "II", "III", "IV", "V", "VI", "VII", "VIII"]
    if (class >= 1 .and. class <= 8) then
      text = trim(numerals(class))
    else
      text = "?"
    end if
  end function roman

end module kinetostat_plans_structure
