!> A deck's lines cut into records (a deck with 10^6 values on one line
!> must not cost the longest line times the number of lines): a deck read from records cut
!> at any width reads exactly as from whole lines — same values, same errors naming the same
!> line and assignment, same capacities, same group, same lines, same overrides — for random
!> decks (values, repeat counts, nulls, sections, quoted texts with separators, comments,
!> tabs, CRLF, a byte-order mark, errors) and for every bundled deck run to its output.
module test_records
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, load_deck, deck_source_from_text, read_group_name, &
    deck_array_capacities, deck_line_count, deck_line, deck_context_t, namelist_probe_t, unset_real
  use kinetostat_override, only: override_t, apply_overrides
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_registry, only: create_mechanism
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_run, only: run_options_t, run_mechanism, format_table, format_json
  use kinetostat_text, only: int_str
  use test_harness, only: test_counts_t, check_true, long_checks
  implicit none
  private
  public :: run_records_tests

  !> Widths the lines are cut at (huge(1): whole lines) besides the one chosen.
  integer, parameter :: widths(*) = [1, 2, 3, 5, 8, 13, 21, 40, 77]
  !> The widths the bundled decks run at without `tools/test --long` (with it: all of `widths`).
  integer, parameter :: sample_widths(*) = [1, 5, 21]

  !> The bundled decks (every mechanism).
  character(len=*), parameter :: decks(*) = [character(len=36) :: &
    "data/pr3207.nml", "data/pr3050.nml", "data/sixbar.nml", "data/sixbar_example.nml", &
    "data/assur_fourbar.nml", "data/assur_fourbar_global.nml", "data/assur_pr3050.nml", &
    "data/assur_pr3050_friction.nml", "data/assur_sixbar.nml", "data/assur_toggle.nml", &
    "data/cam_flat.nml", "data/cam_translating.nml", "data/friction_slider_crank.nml", &
    "data/gears_bevel.nml", "data/gears_planetary.nml", "docs/examples/engine.nml"]

contains

  !> All tests of this suite.
  subroutine run_records_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_cut_places(t)
    call test_random_decks(t)
    call test_bundled_decks(t)
  end subroutine run_records_tests

  !> Where a long line is cut: after commas and blanks outside quotes, parentheses and
  !> comments, never before a comma; a comment is cut into records that start with '!'.
  subroutine test_cut_places(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: src
    character(len=*), parameter :: lf = achar(10)
    call deck_source_from_text("d", "&g a = 1, 2 ,3, s = 'x, y z', a(2:3) = 4 5 /"//lf, src, cut_width=4)
    call check_true(t, "records: cut after separators only", &
                    join(src) == "|&g|a =|1,|2 ,|3,|s =|'x, y z',| a(2:3) =|4 5|/", join(src))
    call check_true(t, "records: the line is kept", deck_line(src, 1) == "&g a = 1, 2 ,3, s = 'x, y z', a(2:3) = 4 5 /", &
                    deck_line(src, 1))
    call deck_source_from_text("d", "&g a = 1, 2 ! c, d e"//lf//"/", src, cut_width=5)
    call check_true(t, "records: a comment is cut into '!' records", join(src) == "|&g|a =|1,|2 ! c|!, d|!e|/", &
                    join(src))
    call check_true(t, "records: the commented line is kept", deck_line(src, 1) == "&g a = 1, 2 ! c, d e", &
                    deck_line(src, 1))
    call deck_source_from_text("d", "&g a = 1, 2 /"//lf, src)
    call check_true(t, "records: a short deck is not cut", size(src%records) == 1 .and. len(src%records) == 13, &
                    join(src))
  end subroutine test_cut_places

  !> The records of `src` joined, each after a '|', without their padding.
  function join(src) result(text)
    type(deck_source_t), intent(in) :: src
    character(len=:), allocatable :: text
    integer :: r
    text = ""
    do r = 1, size(src%records)
      text = text//"|"//trim(src%records(r))
    end do
  end function join

  !> What a deck reads as: the namelist READ's status, message and values, or the probe's
  !> message naming line and assignment; the capacities, the group and the lines.
  function reading(src) result(said)
    type(deck_source_t), intent(in) :: src
    character(len=:), allocatable :: said
    real(wp), allocatable :: a(:)
    real(wp) :: b
    character(len=2000) :: s
    logical :: l
    integer :: ios, capacity(1), k
    character(len=512) :: msg
    character(len=:), allocatable :: group
    character(len=64) :: bits
    type(error_t), allocatable :: error
    type(namelist_probe_t) :: probe
    type(deck_context_t) :: ctx
    namelist /g/ a, b, s, l
    capacity = deck_array_capacities(src, "g", ["a"])
    said = "capacity "//int_str(capacity(1))
    call read_group_name(src, group, error)
    if (allocated(error)) then
      said = said//" no group: "//error%message
    else
      said = said//" group "//group
    end if
    do k = 1, deck_line_count(src)
      said = said//new_line("a")//deck_line(src, k)
    end do
    allocate (a(400), source=unset_real)
    b = unset_real
    s = "-"
    l = .false.
    msg = ""
    read (src%records, nml=g, iostat=ios, iomsg=msg)
    ! (gfortran's iomsg may name a value up to a record's end: compared through the probe's
    ! message only, which is what a user sees)
    said = said//new_line("a")//"ios "//int_str(ios)
    if (ios == 0) then
      do k = 1, size(a)
        write (bits, '(z16)') transfer(a(k), 0_int64)
        said = said//" "//trim(bits)
      end do
      write (bits, '(z16)') transfer(b, 0_int64)
      said = said//" b "//trim(bits)//" s ["//trim(s)//"] l "//merge("T", "F", l)
    else
      ctx%path = "d"
      ctx%group = "g"
      call probe%start(src, ios, msg)
      do while (probe%more(src))
        a = unset_real
        read (probe%records, nml=g, iostat=ios, iomsg=msg)
        call probe%take(ios, msg)
      end do
      call probe%report(src, ctx, error)
      said = said//new_line("a")//error%message
    end if
  end function reading

  !> Random decks read from records cut at every width of `widths` and at the chosen one
  !> as from whole lines; the same with an override written in.
  subroutine test_random_decks(t)
    type(test_counts_t), intent(inout) :: t
    !> Random decks: of the default run, and with `tools/test --long` (the first are the same;
    !> the default run's 40 take 0.6 s of processor time in the checks' build, 100 took 1.5 s).
    integer, parameter :: sample_decks = 40, long_decks = 600
    integer :: n_decks
    character(len=:), allocatable :: text, whole, cut, first_bad
    type(deck_source_t) :: src, patched
    type(override_t) :: over(1)
    integer :: k, w, n_seed, mismatches, errors, cut_decks
    call random_seed(size=n_seed)
    call random_seed(put=[(104729 * k + 7, k=1, n_seed)])
    n_decks = merge(long_decks, sample_decks, long_checks())
    mismatches = 0
    errors = 0
    cut_decks = 0
    over(1)%name = "b"
    over(1)%value = "7.5"
    do k = 1, n_decks
      text = random_deck()
      call deck_source_from_text("d", text, src, cut_width=huge(1))
      whole = reading(src)
      if (index(whole, "ios 0 ") == 0) errors = errors + 1
      call apply_overrides(src, over, patched)
      whole = whole//new_line("a")//"patched: "//reading(patched)
      do w = 1, size(widths) + 1
        ! the last: the width chosen (cut_width < 1)
        call deck_source_from_text("d", text, src, cut_width=merge(-1, widths(min(w, size(widths))), w > size(widths)))
        if (size(src%records) > deck_line_count(src)) cut_decks = cut_decks + 1
        cut = reading(src)
        call apply_overrides(src, over, patched)
        cut = cut//new_line("a")//"patched: "//reading(patched)
        if (cut /= whole) then
          mismatches = mismatches + 1
          if (.not. allocated(first_bad)) first_bad = "width "//int_str(widths(min(w, size(widths))))//" deck:"// &
            new_line("a")//text//new_line("a")//"whole lines:"//new_line("a")//whole//new_line("a")//"records:"// &
            new_line("a")//cut//new_line("a")//"the records:"//new_line("a")//join(src)
        end if
      end do
    end do
    if (.not. allocated(first_bad)) first_bad = ""
    call check_true(t, "records: random decks cut at any width read as whole lines ("//int_str(n_decks)// &
                    " decks, "//int_str(errors)//" failing, "//int_str(cut_decks)//" cuts)", mismatches == 0, &
                    int_str(mismatches)//" differ, first: "//first_bad)
  contains
    !> A whole number from lo to hi.
    integer function pick(lo, hi)
      integer, intent(in) :: lo, hi
      real(wp) :: u
      call random_number(u)
      pick = lo + min(hi - lo, int(u * real(hi - lo + 1, wp)))
    end function pick

    !> A deck of group g, its lines long (many items each), with errors now and then.
    function random_deck() result(deck)
      character(len=:), allocatable :: deck
      character(len=*), parameter :: lf = achar(10), cr = achar(13), tab = achar(9)
      character(len=*), parameter :: seps(*) = [character(len=12) :: ", ", " ", ",", "  ,  ", ",,", &
        ", ,", tab, ","//tab, "   "]
      character(len=*), parameter :: values(*) = [character(len=24) :: "1.5", "-2", "3*4.25", "2*", &
        "1e3", "0.125d0", "+7.", "'a, b'", "oops", "0,5", ".true.", "1*-3"]
      character(len=*), parameter :: texts(*) = [character(len=32) :: "'p = q / r, ''t'' = 1 2'", &
        '"x ! y, z"', "'&g a = 1'", "'a' 'b'", "'unterminated", "2*'r s'"]
      character(len=*), parameter :: comments(*) = [character(len=40) :: " ! it's a, b / c", &
        " ! &g a = 9 $", "! x = 1, 2, 3", " !"]
      character(len=:), allocatable :: eol
      integer :: n_lists, i, j, lo, target
      eol = lf
      if (pick(0, 4) == 0) eol = cr//lf
      deck = ""
      if (pick(0, 4) == 0) deck = char(239)//char(187)//char(191)
      if (pick(0, 2) == 0) deck = deck//"! a deck, it's &g = 1, 2"//eol
      deck = deck//"&g"
      if (pick(0, 1) == 0) deck = deck//eol
      n_lists = pick(1, 5)
      do i = 1, n_lists
        target = pick(1, 9)
        select case (target)
        case (1, 2, 3); deck = deck//" a ="
        case (4); deck = deck//" a("//int_str(pick(1, 40))//") ="
        case (5)
          lo = pick(1, 30)
          deck = deck//" A("//int_str(lo)//":"//int_str(lo + pick(0, 10))//")="
        case (6); deck = deck//" b = "
        case (7); deck = deck//" s ="
        case (8); deck = deck//" l = "
        case default
          if (pick(0, 9) == 0) then
            deck = deck//" zz = "
          else
            deck = deck//" a = "
          end if
        end select
        do j = 1, pick(0, 30)
          if (target == 6 .and. j > 1 .and. pick(0, 9) > 0) exit
          if (target == 7 .or. target == 8) then
            ! a text or a logical (now and then a wrong value or too many)
            if (target == 7) deck = deck//" "//trim(texts(pick(1, size(texts) - 1)))
            if (target == 8) deck = deck//" "//trim(values(11))
            if (pick(0, 9) > 0) exit
          end if
          select case (pick(1, 20))
          case (1)
            if (pick(0, 9) == 0) deck = deck//" "//trim(texts(pick(1, size(texts))))
          case (2); deck = deck//trim(comments(pick(1, size(comments))))//eol
          case (3); deck = deck//eol
          case (4, 5, 6, 7)
            deck = deck//" "//int_str(pick(0, 99))//"."//int_str(pick(0, 999))
          case (8)
            if (pick(0, 40) == 0) then
              deck = deck//" "//trim(values(pick(1, size(values))))
            else
              deck = deck//" "//trim(values(pick(1, 7)))
            end if
          case default; deck = deck//" "//int_str(pick(1, 6))//"*"//int_str(pick(0, 9))
          end select
          deck = deck//trim(seps(pick(1, size(seps))))
        end do
        if (pick(0, 2) == 0) deck = deck//eol
      end do
      deck = deck//" /"
      if (pick(0, 1) == 0) deck = deck//eol
      if (pick(0, 2) == 0) deck = deck//" a = 1 2 3, it's after the group"//eol
    end function random_deck
  end subroutine test_random_decks

  !> Every bundled deck, its lines cut at several widths (three; all nine with `tools/test
  !> --long`), runs to the same output (table and JSON) or error as from whole lines; also
  !> with an unknown variable and with a value that is not a number (the same message, naming
  !> the same line and assignment).
  subroutine test_bundled_decks(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    character(len=:), allocatable :: text, whole, cut, bad, line
    integer :: d, k, w, f, runs, v
    integer, allocatable :: cut_widths(:)
    logical :: group_seen
    if (long_checks()) then
      allocate (cut_widths, source=widths)
    else
      allocate (cut_widths, source=sample_widths)
    end if
    runs = 0
    bad = ""
    do d = 1, size(decks)
      call load_deck(trim(decks(d)), source, error)
      if (allocated(error)) then
        bad = bad//" "//error%message
        cycle
      end if
      do v = 1, 3
        ! the deck; with an unknown variable after the group's line; with a value that is
        ! not a number in its first assignment
        text = ""
        group_seen = .false.
        do k = 1, deck_line_count(source)
          line = deck_line(source, k)
          if (v == 3 .and. group_seen .and. index(line, " = ") > 0 .and. &
              (index(line, "!") == 0 .or. index(line, "!") > index(line, " = "))) then
            line = line(1:index(line, " = ") + 2)//"oops, "//line(index(line, " = ") + 3:)
            group_seen = .false.
          end if
          text = text//line//new_line("a")
          if (.not. group_seen .and. index(adjustl(line), "&") == 1) then
            if (v == 2) text = text//"  zz_typo = 1, 2, 3 ! not in the group"//new_line("a")
            if (v == 3) group_seen = .true.
          end if
        end do
        do f = 1, 2
          whole = run_text(trim(decks(d)), text, huge(1), f)
          if (v > 1 .and. index(whole, "error 2: ") /= 1) bad = bad//" "//trim(decks(d))//" variant "// &
            int_str(v)//" gave no input error: "//whole(1:min(len(whole), 200))
          do w = 1, size(cut_widths)
            cut = run_text(trim(decks(d)), text, cut_widths(w), f)
            runs = runs + 1
            if (cut /= whole) bad = bad//" "//trim(decks(d))//" variant "//int_str(v)//" at width "// &
              int_str(cut_widths(w))//": "//cut(1:min(len(cut), 200))//" instead of "//whole(1:min(len(whole), 200))
          end do
        end do
      end do
    end do
    call check_true(t, "records: bundled decks cut at any width run as whole lines ("//int_str(runs)//" runs)", &
                    len(bad) == 0, bad)
  end subroutine test_bundled_decks

  !> The output (format 1: table, 2: JSON) or error of a deck given as text, its lines cut at `width`.
  function run_text(name, text, width, format) result(said)
    character(*), intent(in) :: name, text
    integer, intent(in) :: width, format
    character(len=:), allocatable :: said
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    class(mechanism_t), allocatable :: mech
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    type(run_options_t) :: options
    character(len=:), allocatable :: group
    call deck_source_from_text(name, text, source, cut_width=width)
    call read_group_name(source, group, error)
    if (allocated(error)) then
      said = error%message
      return
    end if
    options%format = format_table
    if (format == 2) options%format = format_json
    call create_mechanism(group, mech)
    call run_mechanism(mech, group, source, options, table, out, error)
    if (allocated(error)) then
      said = "error "//int_str(error%code)//": "//error%message
    else
      said = out%text()
    end if
  end function run_text

end module test_records
