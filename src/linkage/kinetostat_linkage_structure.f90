!> Structural analysis of a `&linkage` deck as the course does it: degrees of freedom by
!> Chebyshev's formula W = 3n - 2p5 - p4, then the decomposition into input units and Assur
!> groups. Starting from the frame, the smallest set of the remaining links whose pairs (to
!> each other and to the links found before) determine them is the next unit: 3 equations
!> per link against 2 per pair and 1 per drive on those pairs. A set with a drive is an input
!> unit (class I); without, an Assur group: two links and three pairs a class-II dyad (RRR,
!> RRP, RPR, PRP, RPP), four links and six pairs with a link of three pairs in the group a
!> class-III group of order 3 (a ternary base link and three binary links), six links and
!> nine pairs whose five inner pairs join two ternary base links to each other and to two
!> binary links each a class-III group of order 4 (four external pairs), four links in one
!> closed contour a class-IV group of order 2.
module kinetostat_linkage_structure
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_labels, only: lang_ru, echo_name
  use kinetostat_linkage, only: linkage_t, linkage_unit_t, pair_r, pair_row, drive_row
  use kinetostat_plans_structure, only: roman, unit_description
  implicit none
  private
  public :: analyse_structure, structure_lines, structure_formula

  !> Largest unit searched (links).
  integer, parameter :: max_unit_links = 8

contains

  !> W, the drive count check and the decomposition into units (mech%units); `ctx` names the
  !> deck and group in messages.
  pure subroutine analyse_structure(mech, ctx, error)
    !> The linkage (links, pairs, drives set); its units are filled.
    type(linkage_t), intent(inout) :: mech
    !> "deck: group linkage" for messages.
    character(*), intent(in) :: ctx
    type(error_t), allocatable, intent(out) :: error
    logical, allocatable :: known(:), driven(:)
    integer, allocatable :: rest(:), pick(:), best(:)
    type(linkage_unit_t), allocatable :: units(:)
    integer :: n, p5, w, nd, s, i, eq, k
    logical :: found, more
    n = size(mech%links)
    p5 = size(mech%pairs)
    nd = size(mech%drives)
    w = 3 * n - 2 * p5
    if (w /= nd) then
      if (w > nd) then
        call fatal_error(error, exit_input, ctx//": W = 3n - 2p5 = 3 x "//int_str(n)//" - 2 x "//int_str(p5)//" = "// &
          int_str(w)//" but "//int_str(nd)//" drive(s): "//int_str(w - nd)// &
          " constraint(s) missing (add a pair or a drive)")
      else
        call fatal_error(error, exit_input, ctx//": W = 3n - 2p5 = 3 x "//int_str(n)//" - 2 x "//int_str(p5)//" = "// &
          int_str(w)//" but "//int_str(nd)//" drive(s): "//int_str(nd - w)// &
          " surplus constraint(s) (remove a pair or a drive)")
      end if
      return
    end if
    allocate (known(0:n), source=.false.)
    known(0) = .true.
    allocate (driven(p5), source=.false.)
    do k = 1, nd
      driven(mech%drives(k)%pair) = .true.
    end do
    allocate (units(0))
    do while (.not. all(known))
      rest = pack([(i, i=1, n)], .not. known(1:n))
      found = .false.
      do s = 1, min(size(rest), max_unit_links)
        ! combinations of s of the remaining links, in lexicographic order
        pick = [(i, i=1, s)]
        do
          eq = equations(rest(pick))
          if (eq > 3 * s) then
            call fatal_error(error, exit_input, ctx//": links "//id_list(rest(pick))//" have "//int_str(eq - 3 * s)// &
              " surplus constraint(s) (their pairs to each other and to the links before give "//int_str(eq)// &
              " equations for "//int_str(3 * s)//" coordinates)")
            return
          end if
          if (eq == 3 * s) then
            best = rest(pick)
            found = .true.
            exit
          end if
          call next_pick(pick, size(rest), more)
          if (.not. more) exit
        end do
        if (found) exit
      end do
      if (.not. found) then
        call fatal_error(error, exit_input, ctx//": links "//id_list(rest)// &
          " do not decompose into Assur groups (no set of them is determined by its pairs to the links before)")
        return
      end if
      units = [units, classify(best)]
      known(best) = .true.
    end do
    call move_alloc(units, mech%units)
  contains
    !> Equations the pairs (and drives) of links `set` give with the known links.
    pure integer function equations(set)
      integer, intent(in) :: set(:)
      integer :: kk
      equations = 0
      do kk = 1, p5
        if (counts(kk, set)) then
          equations = equations + 2
          if (driven(kk)) equations = equations + 1
        end if
      end do
    end function equations
    !> Pair kk joins a link of `set` to a link of `set` or a known one.
    pure logical function counts(kk, set)
      integer, intent(in) :: kk, set(:)
      logical :: ina, inb
      ina = any(set == mech%pairs(kk)%a)
      inb = any(set == mech%pairs(kk)%b)
      counts = (ina .or. inb) .and. (ina .or. known(mech%pairs(kk)%a)) .and. (inb .or. known(mech%pairs(kk)%b))
    end function counts
    !> The unit of links `set`: rows, class, order, kind, label.
    pure function classify(set) result(unit)
      integer, intent(in) :: set(:)
      type(linkage_unit_t) :: unit
      integer, allocatable :: internal(:), ext(:), inner(:)
      integer :: kk, dd, j
      logical :: has_drive
      allocate (unit%links(size(set)))
      unit%links(:) = set
      allocate (unit%rows(0), ext(0), inner(0))
      has_drive = .false.
      do kk = 1, p5
        if (.not. counts(kk, set)) cycle
        unit%rows = [unit%rows, pair_row(kk), pair_row(kk) + 1]
        if (any(set == mech%pairs(kk)%a) .and. any(set == mech%pairs(kk)%b)) then
          inner = [inner, kk]
        else
          ext = [ext, kk]
        end if
      end do
      do dd = 1, nd
        if (counts(mech%drives(dd)%pair, set)) then
          unit%rows = [unit%rows, drive_row(mech, dd)]
          has_drive = .true.
        end if
      end do
      unit%order = size(ext)
      if (has_drive) then
        unit%class = 1
        unit%label = "I("//id_list(known_ends(ext), set)//")"
        return
      end if
      allocate (internal(size(set)), source=0)
      do j = 1, size(set)
        internal(j) = count(mech%pairs(inner)%a == set(j) .or. mech%pairs(inner)%b == set(j))
      end do
      if (size(set) == 2 .and. size(inner) == 1 .and. size(ext) == 2) then
        unit%class = 2
        unit%kind = dyad_kind(set, inner(1), ext)
      else if (size(set) == 4 .and. size(inner) == 3 .and. any(internal == 3)) then
        unit%class = 3
      else if (size(set) == 6 .and. size(inner) == 5 .and. size(ext) == 4 .and. count(internal == 3) == 2 .and. &
               count(internal == 1) == 4) then
        ! (five inner pairs of six links: no closed contour; the two ternary links are joined)
        unit%class = 3
      else if (size(set) == 4 .and. size(inner) == 4 .and. all(internal == 2)) then
        unit%class = 4
      end if
      unit%label = roman(unit%class)//"("//id_list(set)//")"
    end function classify
    !> The known links the external pairs `ext` join (the frame first).
    pure function known_ends(ext) result(ends)
      integer, intent(in) :: ext(:)
      integer, allocatable :: ends(:)
      integer :: kk, e
      allocate (ends(0))
      do kk = 1, size(ext)
        e = mech%pairs(ext(kk))%a
        if (.not. known(e)) e = mech%pairs(ext(kk))%b
        if (.not. known(e)) cycle
        if (.not. any(ends == e)) ends = [ends, e]
      end do
    end function known_ends
    !> The dyad's kind: outer pair of its first link, inner pair, outer pair of the second,
    !> as the course names the five kinds.
    pure function dyad_kind(set, inner, ext) result(kind)
      integer, intent(in) :: set(2), inner, ext(2)
      character(len=3) :: kind
      integer :: e1, e2
      e1 = ext(1); e2 = ext(2)
      if (.not. (mech%pairs(e1)%a == set(1) .or. mech%pairs(e1)%b == set(1))) then
        e1 = ext(2); e2 = ext(1)
      end if
      kind = letter(e1)//letter(inner)//letter(e2)
      if (kind == "PRR") kind = "RRP"
      if (kind == "PPR") kind = "RPP"
    end function dyad_kind
    pure function letter(kk) result(c)
      integer, intent(in) :: kk
      character(len=1) :: c
      c = merge("R", "P", mech%pairs(kk)%kind == pair_r)
    end function letter
    !> Link numbers (deck ids; 0..n internal) as "2,3,4": `first` (internal indices, the
    !> frame as 0) then `second`.
    pure function id_list(first, second) result(text)
      integer, intent(in) :: first(:)
      integer, intent(in), optional :: second(:)
      character(len=:), allocatable :: text
      integer, allocatable :: all(:)
      integer :: kk, m
      m = size(first)
      if (present(second)) m = m + size(second)
      allocate (all(m))
      all(1:size(first)) = first
      if (present(second)) all(size(first) + 1:) = second
      text = ""
      do kk = 1, size(all)
        if (kk > 1) text = text//","
        text = text//int_str(id_of(all(kk)))
      end do
    end function id_list
    pure integer function id_of(i)
      integer, intent(in) :: i
      if (i == 0) then
        id_of = mech%frame_id
      else
        id_of = mech%links(i)%id
      end if
    end function id_of
  end subroutine analyse_structure

  !> Next combination of s indices from 1..m in lexicographic order; false after the last.
  pure subroutine next_pick(pick, m, more)
    integer, intent(inout) :: pick(:)
    integer, intent(in) :: m
    !> False after the last combination.
    logical, intent(out) :: more
    integer :: i, s, j
    s = size(pick)
    more = .false.
    do i = s, 1, -1
      if (pick(i) < m - s + i) then
        pick(i) = pick(i) + 1
        do j = i + 1, s
          pick(j) = pick(j - 1) + 1
        end do
        more = .true.
        return
      end if
    end do
  end subroutine next_pick

  !> The structure formula: the units in the order found, "I(0,1) -> III(2,3,4,5)".
  pure function structure_formula(mech) result(text)
    !> The analysed linkage.
    type(linkage_t), intent(in) :: mech
    character(len=:), allocatable :: text
    integer :: u
    text = ""
    do u = 1, size(mech%units)
      if (u > 1) text = text//" -> "
      text = text//mech%units(u)%label
    end do
  end function structure_formula

  !> The printed structural analysis, one line per element (lang_en or lang_ru: the English
  !> lines in the words the Russian table's echo uses, labels' echo_name).
  pure subroutine structure_lines(mech, lang, lines)
    !> The analysed linkage.
    type(linkage_t), intent(in) :: mech
    !> Language.
    integer, intent(in) :: lang
    !> The lines (without the leading indentation).
    character(len=160), allocatable, intent(out) :: lines(:)
    integer :: n, p5, u, top, i
    n = size(mech%links)
    p5 = size(mech%pairs)
    allocate (lines(0))
    call push(lines, "STRUCTURAL ANALYSIS")
    call push(lines, "MOVING LINKS n = "//int_str(n)//", LOWER PAIRS p5 = "//int_str(p5)//", HIGHER PAIRS p4 = 0")
    call push(lines, "W = 3n - 2p5 - p4 = 3 x "//int_str(n)//" - 2 x "//int_str(p5)//" - 0 = "//int_str(3 * n - 2 * p5)// &
              " = NUMBER OF DRIVES")
    top = 1
    do u = 1, size(mech%units)
      associate (un => mech%units(u))
        top = max(top, un%class)
        if (un%class == 0) top = 99
        call push(lines, un%label//"  "//unit_description(un%class, size(un%links), un%kind))
      end associate
    end do
    call push(lines, "STRUCTURE FORMULA: "//structure_formula(mech))
    call push(lines, "CLASS OF THE MECHANISM: "//roman(merge(top, 0, top < 99)))
    if (lang /= lang_ru) return
    do i = 1, size(lines)
      lines(i) = echo_name(trim(lines(i)), lang_ru)
    end do
  end subroutine structure_lines

  !> Appends a line to `lines`.
  pure subroutine push(lines, text)
    !> The lines so far.
    character(len=160), allocatable, intent(inout) :: lines(:)
    !> The new line.
    character(*), intent(in) :: text
    character(len=160), allocatable :: more(:)
    allocate (more(size(lines) + 1))
    more(1:size(lines)) = lines
    more(size(more)) = text
    call move_alloc(more, lines)
  end subroutine push

end module kinetostat_linkage_structure
