!> Every declared column is whole and every legacy table agrees with its declarations: for
!> bundled decks of every kind, each column with a unit has a Russian unit, each column with
!> a heading has a Russian heading, and each heading the declarations give (English and
!> Russian) is printed by the kind's RESULTS layout. The checker itself is shown to fail on a
!> column declared without a Russian unit and on a heading a layout does not print.
module test_columns
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_registry, only: create_mechanism
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_step_table, only: step_table_t, column_t, column, col_other, col_force, col_force_angle
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_labels, only: lang_en, lang_ru
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use kinetostat_kinds, only: wp
  use kinetostat_assur_columns, only: force_length, assur_row_size, assur_columns
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck
  use kinetostat_text, only: int_str
  use test_harness, only: test_counts_t, check_true, next, hex
  implicit none
  private
  public :: run_columns_tests

  !> `&assur` decks with every kind of row: prismatic pairs (their N and M columns), the
  !> force components, a driving actuator (F_drive and the stroke), friction, a flywheel.
  character(*), parameter :: assur_decks(*) = [character(len=40) :: &
    "data/assur_fourbar.nml", "data/assur_slider_crank.nml", "data/assur_sixbar.nml", "data/assur_pr3050.nml", &
    "data/assur_pr3050_friction.nml", "data/assur_pr3207.nml", "data/assur_pr3207_flywheel.nml", &
    "data/assur_engine_flywheel.nml", "data/friction_fourbar_resist.nml", "data/friction_slider_crank.nml"]

  !> Decks of every kind: the linkage family with its prismatic pairs, actuators and
  !> friction, the dynamics columns, the gears, cams and design kinds.
  character(*), parameter :: decks(*) = [character(len=40) :: &
    "data/pr3207.nml", "data/pr3207_flywheel.nml", "data/pr3050.nml", "data/sixbar.nml", &
    "data/sixbar_flywheel.nml", "data/assur_pr3207_friction.nml", "data/assur_pr3050_friction.nml", &
    "data/assur_fourbar.nml", "data/friction_slider_crank.nml", "data/linkage_slider_crank.nml", &
    "data/linkage_friction_slider_crank.nml", "data/fivebar.nml", "data/gears_reducer.nml", &
    "data/gears_planetary.nml", "data/cam_flat.nml", "data/cam_translating.nml", &
    "data/gear_geometry_shift.nml", "data/planetary_synthesis.nml", "data/cam_profile_roller.nml"]

contains

  subroutine run_columns_tests(t)
    type(test_counts_t), intent(inout) :: t
    integer :: i
    call test_checker_fails(t)
    call test_force_length(t)
    do i = 1, size(assur_decks)
      call test_row_size(t, trim(assur_decks(i)))
    end do
    do i = 1, size(decks)
      call test_deck(t, trim(decks(i)), .false.)
    end do
    ! --frame link: the link-axes columns' headings
    call test_deck(t, "data/assur_pr3050_friction.nml", .true.)
    call test_deck(t, "data/linkage_slider_crank.nml", .true.)
  end subroutine run_columns_tests

  !> The assur rows' force_length gives hypot's bits: random components over the whole
  !> range of exponents (each side of its thresholds) and of ratios, near-equal pairs, and
  !> zeros, subnormals, infinities and NaN.
  subroutine test_force_length(t)
    type(test_counts_t), intent(inout) :: t
    real(wp) :: x, y, special(7)
    integer(int64) :: state
    integer :: i, j, bad
    !> The first difference (its operands and both results in hexadecimal).
    character(len=160) :: first
    state = 88172645463325252_int64
    bad = 0
    first = " "
    do i = 1, 400000
      x = random_value(-620, 620)
      select case (mod(i, 4))
      case (0)
        y = random_value(-620, 620)
      case (1)
        ! a ratio within 2**-60 .. 2**4 (the negligible threshold 2**-54 among them)
        y = x * random_value(-60, 4)
      case (2)
        ! nearly equal (the kernel's first branch)
        y = x * (1.0_wp + random_value(-52, -1))
      case default
        y = x * random_value(-3, 3)
      end select
      call compare(x, y)
    end do
    special = [0.0_wp, -0.0_wp, tiny(1.0_wp) / 8.0_wp, huge(1.0_wp), ieee_value(1.0_wp, ieee_positive_inf), &
      ieee_value(1.0_wp, ieee_quiet_nan), 1.5_wp]
    do i = 1, size(special)
      do j = 1, size(special)
        call compare(special(i), special(j))
        call compare(-special(i), special(j))
      end do
    end do
    call check_true(t, "force_length is hypot bit for bit", bad == 0, int_str(bad)//" differ, first: "//trim(first))
  contains
    !> One comparison (the first difference kept for the message).
    subroutine compare(a, b)
      real(wp), intent(in) :: a, b
      real(wp) :: h, g
      h = hypot(a, b)
      g = force_length(a, b)
      if (transfer(h, 1_int64) == transfer(g, 1_int64)) return
      bad = bad + 1
      if (bad == 1) first = "x = "//hex(a)//", y = "//hex(b)//": hypot "//hex(h)//", force_length "//hex(g)
    end subroutine compare
    !> A random value of either sign with a random exponent in lo .. hi.
    real(wp) function random_value(lo, hi) result(v)
      integer, intent(in) :: lo, hi
      integer(int64) :: bits
      bits = next(state)
      v = scale(1.0_wp + real(shiftr(bits, 12), wp) * scale(1.0_wp, -52), &
        lo + int(modulo(shiftr(bits, 1), int(hi - lo + 1, int64))))
      if (btest(bits, 0)) v = -v
    end function random_value
  end subroutine test_force_length

  !> assur_row_size (a row's values, counted without declaring the columns: their Russian
  !> units are looked up in the labels' dictionary) against the columns assur_columns
  !> declares, for an `&assur` deck.
  subroutine test_row_size(t, path)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path
    type(deck_source_t) :: source
    type(assur_deck_t) :: deck
    type(error_t), allocatable :: error
    call load_deck(path, source, error)
    if (.not. allocated(error)) call read_assur_deck(source, deck, error)
    call check_true(t, "row size "//path//" reads", .not. allocated(error), "expected a deck, found an error")
    if (allocated(error)) return
    call check_true(t, "row size "//path, assur_row_size(deck) == size(assur_columns(deck)), &
      "assur_row_size "//int_str(assur_row_size(deck))//", columns declared "//int_str(size(assur_columns(deck))))
  end subroutine test_row_size

  !> The declarations of a deck's run and its legacy table in both languages.
  subroutine test_deck(t, path, link_frame)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path
    !> Run with --frame link.
    logical, intent(in) :: link_frame
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    class(mechanism_t), allocatable :: mech
    type(step_table_t) :: table
    character(len=:), allocatable :: group, problems, printed_en, printed_ru
    call load_deck(path, source, error)
    if (.not. allocated(error)) call read_group_name(source, group, error)
    if (.not. allocated(error)) then
      call create_mechanism(group, mech)
      call mech%read_deck(source, error)
    end if
    if (.not. allocated(error)) then
      table%mechanism = group
      table%deck = path
      table%row_name = "step"
      table%driver = "M1"
      table%link_frame = link_frame
      call mech%solve(table, error)
    end if
    call check_true(t, "columns "//path//" runs", .not. allocated(error), "expected a run, found an error")
    if (allocated(error)) return
    call table%finish_columns()
    printed_en = results_text(mech, table, lang_en)
    printed_ru = results_text(mech, table, lang_ru)
    problems = column_problems(table, printed_en, printed_ru)
    call check_true(t, "columns "//path//merge(" --frame link", "             ", link_frame), len(problems) == 0, &
      problems)
  end subroutine test_deck

  !> The RESULTS lines (and the layout's later section) of the table's first rows.
  function results_text(mech, table, lang) result(text)
    class(mechanism_t), intent(in) :: mech
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    type(text_buffer_t) :: out, later
    call mech%write_results(table, lang, 1, min(2, table%row_count()), out, later)
    text = out%text()//later%text()
  end function results_text

  !> What is wrong with the table's declarations against the printed RESULTS in English and
  !> Russian, one line a problem ("" when nothing): a unit without its Russian unit, a
  !> heading without its Russian heading, a declared heading the layout does not print.
  pure function column_problems(table, printed_en, printed_ru) result(problems)
    type(step_table_t), intent(in) :: table
    character(*), intent(in) :: printed_en, printed_ru
    character(len=:), allocatable :: problems
    integer :: i
    problems = ""
    do i = 1, size(table%columns)
      associate (c => table%columns(i))
        if (len(c%unit) > 0) then
          if (.not. allocated(c%unit_ru)) then
            problems = problems//new_line("a")//"  column "//c%name//": unit '"//c%unit// &
              "': expected a Russian unit, found none (declare unit_ru or add it to the labels)"
          else if (len(c%unit_ru) == 0) then
            problems = problems//new_line("a")//"  column "//c%name//": unit '"//c%unit// &
              "': expected a Russian unit, found ''"
          end if
        end if
        if (.not. allocated(c%heading)) cycle
        if (len(c%heading) == 0) cycle
        if (.not. allocated(c%heading_ru)) then
          problems = problems//new_line("a")//"  column "//c%name//": heading '"//c%heading// &
            "': expected a Russian heading, found none"
          cycle
        end if
        ! link-axes columns are printed only with --frame link, and then instead of the
        ! magnitudes and angles of the pair forces
        if (c%link_axes .neqv. table%link_frame) then
          if (c%link_axes .or. c%kind == col_force .or. c%kind == col_force_angle) cycle
        end if
        ! the gears' value lines print a force's angle beside it as "ANGLE =", and a force
        ! only in the stages that have it (F23, F2H: planetary), not under headings
        if ((c%kind == col_force_angle .or. c%kind == col_force) .and. index(printed_en, " ANGLE =") > 0) cycle
        if (.not. (has_word(printed_en, cut(c%heading)) .or. has_word(printed_en, c%heading))) then
          problems = problems//new_line("a")//"  column "//c%name// &
                     ": expected the heading '"//cut(c%heading)//"' in the English RESULTS, found:"//new_line("a")//printed_en
        end if
        ! a value line ("INTERFERENCE1   =") shows the whole heading, a 12-wide field its cut
        if (.not. (has_word(printed_ru, cut(c%heading_ru)) .or. has_word(printed_ru, c%heading_ru))) then
          problems = problems//new_line("a")//"  column "//c%name// &
                     ": expected the heading '"//cut(c%heading_ru)//"' in the Russian RESULTS, found:"//new_line("a")//printed_ru
        end if
      end associate
    end do
  end function column_problems

  !> A heading as a 12-wide field shows it (longer ones are cut).
  pure function cut(heading) result(text)
    character(*), intent(in) :: heading
    character(len=:), allocatable :: text
    text = heading(1:min(len(heading), 12))
  end function cut

  !> Whether `word` stands in `text` between blanks, line ends or the text's ends.
  pure logical function has_word(text, word)
    character(*), intent(in) :: text, word
    integer :: at, from, after
    has_word = .false.
    from = 1
    do
      at = index(text(from:), word)
      if (at == 0) return
      at = from + at - 1
      after = at + len(word)
      if (at == 1) then
        has_word = .true.
      else
        has_word = text(at - 1:at - 1) == " " .or. text(at - 1:at - 1) == new_line("a")
      end if
      if (has_word .and. after <= len(text)) has_word = text(after:after) == " " .or. text(after:after) == new_line("a")
      if (has_word) return
      from = at + 1
    end do
  end function has_word

  !> The checker fails where it must: a unit without a Russian unit, a heading the RESULTS
  !> do not print (expected vs found printed by the check).
  subroutine test_checker_fails(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    character(len=:), allocatable :: problems
    call table%declare_columns([column("F21", "N", col_force, heading="F21"), &
                                column("X", "N/mm^3", col_other, heading="XQ")])
    problems = column_problems(table, "   F21   XQ", "   F21   XQ")
    call check_true(t, "columns: a unit without its Russian unit is found", &
      index(problems, "column X: unit 'N/mm^3': expected a Russian unit") > 0, &
      "expected the checker to name column X's unit, found: '"//problems//"'")
    problems = column_problems(table, "   F21", "   F21   XQ")
    call check_true(t, "columns: a heading the English RESULTS lack is found", &
      index(problems, "expected the heading 'XQ' in the English RESULTS") > 0, &
      "expected the checker to name heading XQ, found: '"//problems//"'")
    problems = column_problems(table, "   F21   XQ", "   F21   XQ")
    call check_true(t, "columns: a whole declaration passes but for its unit", &
      index(problems, "heading") == 0, "expected no heading problem, found: '"//problems//"'")
  end subroutine test_checker_fails

end module test_columns
