!> Tests of the shared layers: vectors and angles, self-check measures, LAPACK wrapper,
!> and the deck layer (reading decks into memory, the unset sentinel, whole numbers).
module test_foundation
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, exit_geometry, exit_input
  use kinetostat_text, only: number_str, int_str
  use kinetostat_deck, only: deck_source_t, load_deck, deck_source_from_text, read_group_name, &
    deck_context_t, unset_real, unset_bits, is_set, is_whole_in, require_whole, require_set, &
    steps_over_turn, deck_array_capacities, max_deck_array, deck_line_count, deck_line, deck_line_length
  use kinetostat_vec2, only: angle_360_deg, angle_180_deg, cross, perp, rotate, snap_noise
  use kinetostat_selfcheck, only: link_balance, power_mismatch, link_balance_t, balance_add_force, &
    equilibrium_residual
  use kinetostat_lapack, only: solve_dense
  use test_harness, only: test_counts_t, check_close, check_true, operator(.dot.), scratch_path
  implicit none
  private
  public :: run_foundation_tests

contains

  subroutine run_foundation_tests(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: tol = 1.0e-14_wp
    real(wp) :: a(3, 3), x(3), r
    type(error_t), allocatable :: error
    type(link_balance_t) :: links(3)

    ! angles: ranges, zero vector, signed zeros
    call check_close(t, "angle_360 of (-1,-1)", 225.0_wp, angle_360_deg([-1.0_wp, -1.0_wp]), tol, tol)
    call check_close(t, "angle_180 of (-1,-1)", -135.0_wp, angle_180_deg([-1.0_wp, -1.0_wp]), tol, tol)
    call check_close(t, "angle of zero vector", 0.0_wp, angle_360_deg([0.0_wp, -0.0_wp]), 0.0_wp, 0.0_wp)
    call check_close(t, "angle_180 of (-1,-0) is +180", 180.0_wp, angle_180_deg([-1.0_wp, -0.0_wp]), tol, tol)
    call check_close(t, "angle_360 of (1,-1e-300) stays below 360", 0.0_wp, &
                     angle_360_deg([1.0_wp, -1.0e-300_wp]), 0.0_wp, 1.0e-12_wp)
    call check_true(t, "angle_360 < 360", angle_360_deg([1.0_wp, -1.0e-300_wp]) < 360.0_wp, "got 360")
    call check_close(t, "cross", -2.0_wp, cross([1.0_wp, 1.0_wp], [2.0_wp, 0.0_wp]), tol, tol)
    call check_close(t, "perp", 3.0_wp, perp([3.0_wp, 4.0_wp]) .dot. [0.0_wp, 1.0_wp], tol, tol)
    call check_close(t, "rotate 90", 1.0_wp, rotate([1.0_wp, 0.0_wp], pi / 2)  .dot. [0.0_wp, 1.0_wp], tol, tol)
    call check_close(t, "snap_noise keeps", 1.0_wp, sum(snap_noise([0.6_wp, 0.4_wp], 1.0e-9_wp)), tol, tol)
    call check_close(t, "snap_noise zeroes", 0.0_wp, sum(abs(snap_noise([1.0e-13_wp, 0.0_wp], 1.0e-12_wp))), 0.0_wp, 0.0_wp)

    ! residual of a balanced lever: 2 N at x=1 up, 1 N at x=2 down, 1 N at 0 down
    r = equilibrium_residual([link_balance(reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp], [2, 3]), &
                      reshape([0.0_wp, -1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -1.0_wp], [2, 3]), [real(wp) ::])])
    call check_close(t, "balanced lever residual", 0.0_wp, r, 0.0_wp, tol)
    ! the same with a missing 1 N*m couple: moment residual 1 / (2 + 2) = 0.25
    r = equilibrium_residual([link_balance(reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp], [2, 3]), &
                      reshape([0.0_wp, -1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -1.0_wp], [2, 3]), [1.0_wp])])
    call check_close(t, "unbalanced lever residual", 1.0_wp / 5.0_wp, r, tol, tol)
    call check_close(t, "power mismatch scaled by max(|q|,scale)", 0.01_wp / 1.01_wp, &
                     power_mismatch(1.01_wp, 1.0_wp, 1.0_wp), 1.0e-12_wp, 0.0_wp)

    ! shared floor rule: link 1 a short loaded lever (1000 N, arms 1 mm: sum |M_i| = 4 N*m);
    ! link 2 a two-force link whose moments are roundoff (1e-13 N*m against 1000 N * 1 m): its
    ! own moment ratio is 1; judged against 1e-6 of the step's largest sum |r|*|F| (1000 N*m)
    ! it is 1e-10 (against 1e-6 of the largest sum |M_i|, 4 N*m, it would be 2.5e-8, as
    ! pr3050 with g = 0 showed)
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [0.0_wp, 1000.0_wp])
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [1.0e-3_wp, 0.0_wp], [0.0_wp, -2000.0_wp])
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [2.0e-3_wp, 0.0_wp], [0.0_wp, 1000.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [1.0_wp, 1.0e-16_wp], [-1000.0_wp, 0.0_wp])
    call check_close(t, "two-force link: |sum M| / sum |M_i| is 1 (roundoff scale)", 1.0_wp, &
                     abs(links(2)%sum_m) / links(2)%scale_m, 1.0e-12_wp, 0.0_wp)
    r = equilibrium_residual(links(1:2))
    call check_true(t, "two-force link in its step: residual <= 1e-9", r <= 1.0e-9_wp, &
                    "residual "//trim(real_text(r))//", expected <= 1e-9")
    ! the check can still fail: a wrong reaction (999 N instead of 1000 N) on link 2 ...
    links(2) = link_balance_t()
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp], [-999.0_wp, 0.0_wp])
    call check_close(t, "wrong reaction on a loaded link: residual 1/1999", 1.0_wp / 1999.0_wp, &
                     equilibrium_residual(links(1:2)), 1.0e-12_wp, 0.0_wp)
    ! ... and a 1 N force left unbalanced on an otherwise unloaded link (above the floor)
    call balance_add_force(links(3), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp])
    call check_close(t, "unbalanced 1 N on an unloaded link: residual 1", 1.0_wp, &
                     equilibrium_residual(links), 1.0e-12_wp, 0.0_wp)

    ! LAPACK wrapper: a known solution, then a singular matrix -> geometry error
    a = reshape([4.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 3.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 2.0_wp], [3, 3])
    call solve_dense(a, matmul(a, [1.0_wp, -2.0_wp, 3.0_wp]), x, error)
    call check_true(t, "solve_dense ok", .not. allocated(error), "unexpected error")
    call check_close(t, "solve_dense x1", 1.0_wp, x(1), 1.0e-13_wp, 1.0e-13_wp)
    call check_close(t, "solve_dense x2", -2.0_wp, x(2), 1.0e-13_wp, 1.0e-13_wp)
    call check_close(t, "solve_dense x3", 3.0_wp, x(3), 1.0e-13_wp, 1.0e-13_wp)
    a(:, 3) = a(:, 1) + a(:, 2)
    call solve_dense(a, [1.0_wp, 1.0_wp, 1.0_wp], x, error)
    call check_true(t, "solve_dense singular -> error", allocated(error), "no error for a singular matrix")
    if (allocated(error)) call check_true(t, "solve_dense singular -> exit 3", error%code == exit_geometry, &
                                          "wrong exit code")

    call test_int_str(t)
    call test_deck_source(t)
    call test_load_deck(t)
    call test_unset_and_whole(t)
    call test_array_capacities(t)
    call test_capacities_read_as_full(t)
  end subroutine run_foundation_tests

  !> int_str (digit by digit) gives the text of the i0 edit descriptor: the extremes, zero,
  !> every power of ten and its neighbours, both signs.
  subroutine test_int_str(t)
    type(test_counts_t), intent(inout) :: t
    character(len=24) :: buf
    integer :: values(64), i, p, differ
    values(1:4) = [0, huge(0), -huge(0), -huge(0) - 1]
    p = 1
    do i = 0, 9
      values(5 + 6 * i:10 + 6 * i) = [p - 1, p, p + 1, -p + 1, -p, -p - 1]
      if (i < 9) p = p * 10
    end do
    differ = 0
    do i = 1, size(values)
      write (buf, '(i0)') values(i)
      if (int_str(values(i)) /= trim(buf) .or. len(int_str(values(i))) /= len_trim(buf)) then
        differ = differ + 1
        call check_text(t, "int_str = i0", trim(buf), int_str(values(i)))
      end if
    end do
    call check_true(t, "int_str = i0 on 64 values", differ == 0, "see above")
  end subroutine test_int_str

  !> Pass when two texts are equal; both are printed on failure.
  subroutine check_text(t, name, expected, computed)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name, expected, computed
    call check_true(t, name, expected == computed .and. len(expected) == len(computed), &
                    "expected '"//expected//"', computed '"//computed//"'")
  end subroutine check_text

  !> The message of `error`, or "(no error)".
  function message_of(error) result(m)
    type(error_t), allocatable, intent(in) :: error
    character(len=:), allocatable :: m
    if (allocated(error)) then
      m = error%message
    else
      m = "(no error)"
    end if
  end function message_of

  !> deck_array_capacities on hand-written decks: each capacity is at least the highest
  !> element the deck assigns and at most `slack` more (a count includes the next designator;
  !> a section counts from its upper end).
  subroutine test_array_capacities(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10)
    call expect("list", "&g a = 1, 2, 3 /", 3, 1)
    call expect("blank-separated, next variable", "&g a = 1 2 3 b = 4 /", 3, 1)
    call expect("repeat count", "&g a = 3*1.5, 2 /", 4, 1)
    call expect("repeat of nulls", "&g a = 5* /", 5, 1)
    call expect("null values", "&g a = ,,,4 /", 4, 1)
    call expect("subscript", "&g b = 1 a(5) = 1, 2 /", 6, 1)
    call expect("subscript without values", "&g a(5) = /", 5, 0)
    call expect("section, upper case", "&G A(2:4) = 1 2 3 /", 4, 2)
    call expect("subscript written apart", "&g a (7) = 1 /", 7, 1)
    call expect("largest of two lists", "&g a = 1 2 3 4, b = 1, a(2) = 5 /", 4, 1)
    call expect("comment skipped", "&g a = 1 ! 2 3 4 5 6 7"//lf//" 2 /", 2, 1)
    call expect("string with '=', '/', ','", "&g t = 'x = y / z, w', a = 1 2 /", 2, 1)
    call expect("doubled quote", "&g t = 'it''s = 1 2 3 4', a = 1 /", 1, 1)
    call expect("string across lines", "&g t = 'p = 1"//lf//" / a = 1 2 3 4 5 6' a = 1 /", 1, 1)
    call expect("apostrophe before the group", "! don't"//lf//"&g a = 1 2 /", 2, 1)
    call expect("semicolons", "&g a = 1; 2; 3 /", 3, 1)
    call expect("after '/' ignored", "&g a = 1 / a = 1 2 3 4 5 6 7 8", 1, 1)
    call expect("other group first", "&h a = 1 2 3 4 5 6 7 8 /"//lf//"&g a = 1 /", 1, 1)
    call expect("component is not the array", "&g d(1)%a = 9*1 a = 1 /", 1, 1)
    call expect("absent array", "&g b = 1 /", 1, 0)
    call expect("no group", "a = 1 2 3", 1, 0)
    call expect("repeat beyond the cap", "&g a = 2000000*1 /", max_deck_array, 0)
    call expect("subscript beyond the cap", "&g a(1000001) = 1 /", max_deck_array, 0)
  contains
    !> The capacity of `a` in `text` is from `highest` to `highest + slack`; `b`'s is 1.
    subroutine expect(name, text, highest, slack)
      character(*), intent(in) :: name, text
      integer, intent(in) :: highest, slack
      type(deck_source_t) :: src
      integer :: capacity(2)
      call deck_source_from_text("cap", text, src)
      capacity = deck_array_capacities(src, "g", [character(len=1) :: "a", "c"])
      call check_true(t, "capacity: "//name, capacity(1) >= highest .and. capacity(1) <= highest + slack, &
                      "expected "//number_str(real(highest, wp))//" to "//number_str(real(highest + slack, wp))// &
                      ", computed "//number_str(real(capacity(1), wp)))
      call check_true(t, "capacity: "//name//" (array not named)", capacity(2) == 1, &
                      "expected 1, computed "//number_str(real(capacity(2), wp)))
    end subroutine expect
  end subroutine test_array_capacities

  !> Random decks (value lists, repeats, nulls, subscripts, sections, comments, strings with
  !> '=', '/' and quotes, lines after the group's end) read into an array sized by
  !> deck_array_capacities exactly as into a full-size buffer: same success, same values.
  subroutine test_capacities_read_as_full(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10)
    integer, parameter :: decks = 2000, full = 400
    real(wp), allocatable :: a(:)
    real(wp) :: b
    character(len=40) :: s
    character(len=:), allocatable :: text
    type(deck_source_t) :: src
    integer :: k, capacity(1), ios_full, ios_sized, n_seed, mismatches
    real(wp) :: full_values(full)
    character(len=256) :: msg
    character(len=:), allocatable :: first_bad
    namelist /g/ a, b, s
    call random_seed(size=n_seed)
    call random_seed(put=[(7919 * k + 13, k=1, n_seed)])
    mismatches = 0
    do k = 1, decks
      text = random_deck()
      call deck_source_from_text("random", text, src)
      allocate (a(full), source=unset_real)
      read (src%records, nml=g, iostat=ios_full, iomsg=msg)
      full_values = a
      deallocate (a)
      capacity = deck_array_capacities(src, "g", ["a"])
      allocate (a(capacity(1)), source=unset_real)
      read (src%records, nml=g, iostat=ios_sized, iomsg=msg)
      if ((ios_full == 0) .neqv. (ios_sized == 0)) then
        call note_bad()
      else if (ios_full == 0) then
        if (capacity(1) > full) then
          call note_bad()
        else if (any(transfer(full_values(1:capacity(1)), 0_int64, capacity(1)) /= &
                     transfer(a, 0_int64, capacity(1))) .or. any(is_set(full_values(capacity(1) + 1:)))) then
          call note_bad()
        end if
      end if
      deallocate (a)
    end do
    if (.not. allocated(first_bad)) first_bad = ""
    call check_true(t, "capacity: 2000 random decks read as with a full buffer", mismatches == 0, &
                    number_str(real(mismatches, wp))//" differ, first: "//first_bad)
  contains
    subroutine note_bad()
      mismatches = mismatches + 1
      if (.not. allocated(first_bad)) first_bad = text
    end subroutine note_bad

    !> A whole number from lo to hi.
    integer function pick(lo, hi)
      integer, intent(in) :: lo, hi
      real(wp) :: u
      call random_number(u)
      pick = lo + min(hi - lo, int(u * real(hi - lo + 1, wp)))
    end function pick

    function random_deck() result(deck)
      character(len=:), allocatable :: deck
      character(len=*), parameter :: seps(*) = [character(len=24) :: ", ", " ", ",", lf, "; ", &
        " ! x = 1 2 3 don't /"//lf, ",,"]
      integer :: n_lists, i, j, lo, hi
      deck = ""
      if (pick(0, 3) == 0) deck = "! a = 1 2 3 4 5 6 7 8 9 it's"//lf
      deck = deck//"&g"//lf
      n_lists = pick(1, 4)
      do i = 1, n_lists
        select case (pick(1, 6))
        case (1, 2); deck = deck//" a ="
        case (3); deck = deck//" a("//int_text(pick(1, 40))//") ="
        case (4)
          ! a section gets exactly its length in plain values: gfortran's READ of a section
          ! given more values (through a repeat count) fails or not with the parity of the
          ! array's size (gfortran 12), which no capacity can reproduce
          lo = pick(1, 30)
          hi = lo + pick(0, 10)
          deck = deck//" A("//int_text(lo)//":"//int_text(hi)//") ="
          do j = lo, hi
            deck = deck//" "//int_text(j)//".25"//trim(seps(pick(1, 5)))
          end do
          deck = deck//lf
          cycle
        case (5); deck = deck//" b = 2.5"//trim(seps(pick(1, size(seps))))
        case default; deck = deck//" s = 'p = q / r, ''t'' = 1 2',"//lf
        end select
        if (index(deck(max(1, len(deck) - 2):), "=") == 0) cycle
        do j = 1, pick(0, 12)
          select case (pick(1, 5))
          case (1, 2); deck = deck//" "//int_text(pick(0, 99))//".5"
          case (3); deck = deck//" "//int_text(pick(1, 6))//"*"//int_text(pick(0, 9))
          case (4); deck = deck//" "//int_text(pick(1, 4))//"*"
          case default; deck = deck//""  ! an empty value: nulls come from the separators
          end select
          deck = deck//trim(seps(pick(1, size(seps))))
        end do
        deck = deck//lf
      end do
      deck = deck//" /"//lf
      if (pick(0, 1) == 0) deck = deck//" a = 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20"//lf
    end function random_deck

    function int_text(i) result(txt)
      integer, intent(in) :: i
      character(len=:), allocatable :: txt
      character(len=12) :: buf
      write (buf, '(i0)') i
      txt = trim(buf)
    end function int_text
  end subroutine test_capacities_read_as_full

  !> deck_source_from_text: line splitting, CRLF, BOM, final newline, namelist READ.
  subroutine test_deck_source(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10), cr = achar(13)
    character(len=*), parameter :: bom = char(239)//char(187)//char(191)
    type(deck_source_t) :: src
    type(error_t), allocatable :: error
    character(len=:), allocatable :: group
    real(wp) :: a, b
    integer :: ios
    character(len=256) :: msg
    namelist /grp/ a, b

    call deck_source_from_text("<text>", "&grp"//lf//" a = 1.5,"//lf//lf//" b = 2 /", src)
    call check_text(t, "source name", "<text>", src%path)
    call check_true(t, "4 lines from 3 LFs, no final LF", deck_line_count(src) == 4 .and. size(src%records) == 4, &
                    "got "//number_str(real(deck_line_count(src), wp)))
    call check_true(t, "record length = longest line (9)", len(src%records) == 9, "got "//number_str(real(len(src%records), wp)))
    if (deck_line_count(src) == 4) then
      call check_text(t, "line 1", "&grp", deck_line(src, 1))
      call check_text(t, "empty line 3 kept", "", deck_line(src, 3))
      call check_text(t, "last line without LF kept", " b = 2 /", deck_line(src, 4))
    end if
    a = -1.0_wp; b = -1.0_wp
    read (src%records, nml=grp, iostat=ios, iomsg=msg)
    call check_true(t, "namelist READ from a source without final newline", ios == 0, trim(msg))
    call check_close(t, "namelist READ a", 1.5_wp, a, 0.0_wp, 0.0_wp)
    call check_close(t, "namelist READ b", 2.0_wp, b, 0.0_wp, 0.0_wp)

    call deck_source_from_text("crlf", bom//"&Grp, a = 3"//cr//lf//"/"//cr//lf, src)
    call check_true(t, "CRLF text with final CRLF: 2 lines", deck_line_count(src) == 2, &
                    "got "//number_str(real(deck_line_count(src), wp)))
    if (deck_line_count(src) == 2) then
      call check_text(t, "BOM and CR stripped from line 1", "&Grp, a = 3", deck_line(src, 1))
      call check_text(t, "CR stripped from line 2", "/", deck_line(src, 2))
    end if
    call read_group_name(src, group, error)
    call check_text(t, "group name after a BOM, lower case", "grp", group)
    a = -1.0_wp
    read (src%records, nml=grp, iostat=ios, iomsg=msg)
    call check_true(t, "namelist READ of a CRLF source with BOM", ios == 0 .and. a == 3.0_wp, trim(msg))

    call deck_source_from_text("empty", "", src)
    call check_true(t, "empty text: no lines", deck_line_count(src) == 0 .and. size(src%records) == 0, &
                    "got "//number_str(real(deck_line_count(src), wp)))
    call read_group_name(src, group, error)
    call check_true(t, "empty text: no group -> input error", allocated(error), "no error")
    if (allocated(error)) then
      call check_true(t, "no group -> exit 2", error%code == exit_input, "wrong exit code")
      call check_text(t, "no group message", "empty: no namelist group (a line starting with '&name') found", &
                      error%message)
    end if
  end subroutine test_deck_source

  !> load_deck: a file without a final newline, with CRLF and a BOM; a missing file.
  subroutine test_load_deck(t)
    type(test_counts_t), intent(inout) :: t
    character(len=:), allocatable :: path
    character(len=*), parameter :: lf = achar(10), cr = achar(13)
    character(len=:), allocatable :: long_value
    type(deck_source_t) :: src
    type(error_t), allocatable :: error
    integer :: unit
    long_value = repeat("9", 3000)
    path = scratch_path("load_deck", ".tmp")
    open (newunit=unit, file=path, access='stream', form='unformatted', status='replace', action='write')
    write (unit) char(239)//char(187)//char(191)//"&g"//cr//lf//" x = "//long_value//lf//"/"
    close (unit)
    call load_deck(path, src, error)
    call check_true(t, "load_deck reads the file", .not. allocated(error), message_of(error))
    call check_text(t, "load_deck keeps the path for messages", path, src%path)
    call check_true(t, "load_deck: 3 lines", deck_line_count(src) == 3, "got "//number_str(real(deck_line_count(src), wp)))
    if (deck_line_count(src) == 3) then
      call check_true(t, "load_deck: a 3005-character line is kept whole", deck_line(src, 2) == " x = "//long_value, &
                      "line length "//number_str(real(deck_line_length(src, 2), wp)))
      call check_text(t, "load_deck: BOM and CR stripped", "&g", deck_line(src, 1))
      call check_text(t, "load_deck: last line without newline", "/", deck_line(src, 3))
    end if
    open (newunit=unit, file=path, status='old')
    close (unit, status='delete')
    call load_deck(path, src, error)
    call check_true(t, "load_deck of a missing file -> error", allocated(error), "no error")
    if (allocated(error)) then
      call check_true(t, "missing file -> exit 2", error%code == exit_input, "wrong exit code")
      call check_true(t, "missing file message", index(error%message, path//": cannot open deck: ") == 1, &
                      error%message)
    end if
  end subroutine test_load_deck

  !> The unset sentinel cannot be typed; require_whole; steps_over_turn cannot overflow.
  subroutine test_unset_and_whole(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_context_t) :: ctx
    type(deck_source_t) :: src
    type(error_t), allocatable :: error
    real(wp) :: x, typed(3)
    integer :: value, n, ios
    character(len=256) :: msg
    namelist /nums/ typed
    ctx%path = "d.nml"
    ctx%group = "g"

    x = unset_real
    call check_true(t, "unset_real keeps its payload in other modules", transfer(x, 0_int64) == unset_bits, &
                    "bits lost (a NaN parameter from a .mod file?)")
    call check_true(t, "is_set(unset_real) is false", .not. is_set(x), "true")
    call check_true(t, "is_set(0), is_set(-huge) are true", is_set(0.0_wp) .and. is_set(-huge(1.0_wp)), "false")
    ! NaN typed in a deck: set (not the sentinel), then rejected as not finite
    typed = unset_real
    call deck_source_from_text("nan", "&nums typed = nan, NaN(0x1), -nan /", src)
    read (src%records, nml=nums, iostat=ios, iomsg=msg)
    call check_true(t, "namelist READ of typed NaNs", ios == 0, trim(msg))
    call check_true(t, "typed NaNs are not the sentinel", all(is_set(typed)), "a typed NaN reads as unset_real")
    call require_set(ctx, "typed", typed(2), error)
    call check_text(t, "typed NaN -> must be a finite number", "d.nml: &g: typed: must be a finite number (got NaN)", &
                    message_of(error))

    call check_true(t, "is_whole_in(5, 1, 5)", is_whole_in(5.0_wp, 1, 5), "false")
    call check_true(t, "not is_whole_in(5.5, 1, 9), (0, 1, 5), (6, 1, 5), (NaN)", .not. any(is_whole_in( &
                    [5.5_wp, 0.0_wp, 6.0_wp, unset_real], [1, 1, 1, 1], [9, 5, 5, 5])), "true")
    call require_whole(ctx, "n", 13.0_wp, 1, 1000000, value, error)
    call check_true(t, "require_whole(13) = 13", .not. allocated(error) .and. value == 13, message_of(error))
    call require_whole(ctx, "n", -2147483647.0_wp, 1, 1000000, value, error)
    call check_text(t, "require_whole(-2147483647)", &
                    "d.nml: &g: n: must be a whole number from 1 to 1000000 (got -2147483647)", message_of(error))
    call require_whole(ctx, "n", 2147483648.0_wp, 1, huge(1), value, error)
    call check_text(t, "require_whole(2147483648) beyond default integer", &
                    "d.nml: &g: n: must be a whole number from 1 to 2147483647 (got 2147483648)", message_of(error))
    call require_whole(ctx, "n", 1.5_wp, 1, 1000000, value, error)
    call check_text(t, "require_whole(1.5)", &
                    "d.nml: &g: n: must be a whole number from 1 to 1000000 (got 1.500000000)", message_of(error))
    call require_whole(ctx, "n", unset_real, 1, 1000000, value, error)
    call check_text(t, "require_whole(unset)", "d.nml: &g: n: missing (required variable)", message_of(error))

    call steps_over_turn(ctx, 30.0_wp, unset_real, n, error)
    call check_true(t, "steps_over_turn(30 deg) = 13", .not. allocated(error) .and. n == 13, message_of(error))
    call steps_over_turn(ctx, 1.0e-12_wp, unset_real, n, error)
    call check_true(t, "steps_over_turn(1e-12 deg) -> error naming dphi", &
                    index(message_of(error), "d.nml: &g: dphi: too small") == 1, message_of(error))
    call steps_over_turn(ctx, 30.0_wp, 7.0_wp, n, error)
    call check_true(t, "steps_over_turn with n = 7", .not. allocated(error) .and. n == 7, message_of(error))
  end subroutine test_unset_and_whole

  !> A real in es10.3 for messages.
  pure function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=10) :: text
    write (text, '(es10.3)') x
  end function real_text

end module test_foundation
