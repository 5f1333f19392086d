!> A run solved and written in blocks of rows gives the output of the same run in one block,
!> byte for byte, with the same warnings, self-check figures and errors:
!> bundled decks of six kinds (with warnings, friction, a run that fails at step 2), every text
!> format, blocks of 1, 2, 5 and 7 rows (without `tools/test --long`: half the formats of each
!> deck and one block size, in turn); test/cli/test_block_rows.sh runs every deck it finds in
!> data/ and docs/examples/ through the binary. The spool: text beyond
!> its bound goes to a temporary file that becomes the target only when the run succeeded.
module test_blocks
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_registry, only: create_mechanism
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_run, only: run_options_t, run_mechanism, format_table, format_csv, format_json, format_summary, &
    format_svg, format_plans, format_dxf
  use kinetostat_labels, only: lang_ru
  use kinetostat_spool, only: spool_t
  use kinetostat_text, only: int_str
  use test_harness, only: test_counts_t, check_true, check_close, scratch_path, long_checks
  use kinetostat_kinds, only: wp
  use kinetostat_run_tally, only: run_tally_t, running_max_t, trapezoid_t, flag_count_t, merge_tally
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
  implicit none
  private
  public :: run_blocks_tests

  !> Bundled decks of pr3207, pr3050, sixbar, assur, cam and gears (warnings, friction, a run
  !> that fails at step 2); the other kinds and the dynamics decks: test/cli/test_block_rows.sh.
  character(len=*), parameter :: decks(*) = [character(len=36) :: &
    "data/pr3207.nml", "data/pr3050.nml", "data/sixbar.nml", "data/sixbar_example.nml", &
    "data/assur_fourbar.nml", "data/assur_fourbar_global.nml", "data/assur_pr3050.nml", &
    "data/assur_pr3050_friction.nml", "data/assur_pr3207.nml", "data/assur_pr3207_friction.nml", &
    "data/assur_sixbar.nml", "data/assur_sixbar_friction.nml", "data/assur_sixbar_global.nml", &
    "data/assur_slider_crank.nml", "data/assur_toggle.nml", "data/cam_flat.nml", "data/cam_translating.nml", &
    "data/friction_slider_crank.nml", "data/gears_bevel.nml", "data/gears_planetary.nml", &
    "data/gears_reducer.nml", "docs/examples/engine.nml", "docs/examples/fourbar.nml"]
  !> Rows per block tried against the whole run.
  integer, parameter :: block_sizes(*) = [1, 2, 5, 7]

contains

  !> All tests of this suite.
  subroutine run_blocks_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_run_tally(t)
    call test_blocks_equal_whole(t)
    call test_drawings_in_blocks(t)
    call test_spool(t)
  end subroutine run_blocks_tests

  !> The run tally's merge on figures worked by hand: a run of 6 rows cut into blocks of
  !> 1, 2, 4 and 6 rows gives the figures of the whole run bit for bit (the drive deviation
  !> max|d| / max(scale), not the largest block ratio; the trapezoid term by term; the first
  !> flagged row; the first of two NaN residuals).
  subroutine test_run_tally(t)
    type(test_counts_t), intent(inout) :: t
    !> |M1 - M_d| and the moment scale per row: the largest ratio of a row (0.9/1) is not
    !> the run's, max 0.9 / max 10 = 0.09.
    real(wp), parameter :: dev(6) = [0.1_wp, 0.9_wp, 0.3_wp, 0.2_wp, 0.5_wp, 0.05_wp]
    real(wp), parameter :: scl(6) = [10.0_wp, 1.0_wp, 2.0_wp, 4.0_wp, 3.0_wp, 1.0_wp]
    !> Points of a trapezoid over |dx| (x in deg, integrated in rad).
    real(wp), parameter :: x(6) = [0.0_wp, 30.0_wp, 60.0_wp, 90.0_wp, 120.0_wp, 150.0_wp]
    real(wp), parameter :: y(6) = [1.0_wp, 3.0_wp, -2.0_wp, 0.5_wp, 7.0_wp, 1.0_wp]
    logical, parameter :: flag(6) = [.false., .false., .true., .false., .true., .true.]
    integer, parameter :: sizes(4) = [1, 2, 4, 6]
    real(wp) :: residual(6), area
    type(run_tally_t) :: run, block
    integer :: b, k1, k2, k
    character(len=2) :: tag
    residual = [1.0e-16_wp, 3.0e-16_wp, ieee_value(1.0_wp, ieee_quiet_nan), 2.0e-16_wp, &
                ieee_value(1.0_wp, ieee_quiet_nan), 9.0e-16_wp]
    ! the trapezoid by hand: 0.5 * |dx| in rad * (y(k-1) + y(k)) summed in row order
    area = 0.0_wp
    do k = 2, 6
      area = area + 0.5_wp * (abs(x(k) - x(k - 1)) * (acos(-1.0_wp) / 180.0_wp)) * (y(k - 1) + y(k))
    end do
    do b = 1, size(sizes)
      write (tag, '(i2)') sizes(b)
      run = run_tally_t()
      do k1 = 1, 6, sizes(b)
        k2 = min(6, k1 + sizes(b) - 1)
        block = run_tally_t()
        k = maxloc(residual(k1:k2), 1, mask=.not. ieee_is_nan(residual(k1:k2)))
        if (any(ieee_is_nan(residual(k1:k2)))) k = findloc(ieee_is_nan(residual(k1:k2)), .true., 1)
        block%residual = running_max_t(residual(k1 - 1 + k), k1 - 1 + k, .true.)
        call block%drive_deviation%note(maxval(dev(k1:k2)), maxval(scl(k1:k2)))
        allocate (block%integrals(1), block%flags(1))
        block%integrals(1)%unit = acos(-1.0_wp) / 180.0_wp
        block%integrals(1)%x = x(k1:k2)
        block%integrals(1)%y = y(k1:k2)
        block%flags(1) = flag_count_t(count(flag(k1:k2)), 0)
        if (any(flag(k1:k2))) block%flags(1)%first_row = k1 - 1 + findloc(flag(k1:k2), .true., 1)
        call merge_tally(run, block)
      end do
      call check_close(t, "run tally, blocks of "//tag//": drive deviation max/max", 0.09_wp, &
        run%drive_deviation%ratio(), 1.0e-15_wp, 0.0_wp)
      call check_true(t, "run tally, blocks of "//tag//": trapezoid term by term", &
        run%integrals(1)%area == area, "area differs from the sum in row order")
      call check_true(t, "run tally, blocks of "//tag//": flags 3, first at row 3", &
        run%flags(1)%count == 3 .and. run%flags(1)%first_row == 3, "count or first row")
      call check_true(t, "run tally, blocks of "//tag//": the first NaN residual kept (row 3)", &
        ieee_is_nan(run%residual%value) .and. run%residual%row == 3, "residual row")
    end do
  end subroutine test_run_tally

  !> One run of `path` with `options`: its output (what the spool did not take), and its
  !> report: error text and code, or warnings and self-check figures.
  subroutine run_one(path, options, text, spool, report)
    character(*), intent(in) :: path
    type(run_options_t), intent(in) :: options
    !> The output, then (without `report`) the report.
    character(len=:), allocatable, intent(out) :: text
    type(spool_t), intent(inout), optional :: spool
    !> The report, when asked for apart.
    character(len=:), allocatable, intent(out), optional :: report
    character(len=:), allocatable :: said
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    class(mechanism_t), allocatable :: mech
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    character(len=:), allocatable :: group
    character(len=40) :: figures
    integer :: i
    call load_deck(path, source, error)
    if (.not. allocated(error)) call read_group_name(source, group, error)
    text = ""
    said = ""
    if (allocated(error)) then
      said = "deck error: "//error%message
    else
      call create_mechanism(group, mech)
      call run_mechanism(mech, group, source, options, table, out, error, spool)
      if (allocated(error)) then
        said = "error "//int_str(error%code)//": "//error%message
      else
        text = out%text()
        do i = 1, table%warning_count()
          said = said//"warning: "//table%warnings(i)%text//new_line("a")
        end do
        write (figures, '(2es20.12)') table%run_tally%residual%value, table%run_tally%mismatch%value
        said = said//"self-check: "//figures
      end if
    end if
    if (present(report)) then
      report = said
    else
      text = text//said
    end if
  end subroutine run_one

  !> Blocks of 1, 2, 5, 7 rows (and echo chunks of as many values) against one block, for
  !> every deck in every format with `tools/test --long`; without it, every other format case
  !> of each deck (each format on half the decks) with one size in turn (each deck and each
  !> format meets every size).
  subroutine test_blocks_equal_whole(t)
    type(test_counts_t), intent(inout) :: t
    type(run_options_t) :: options
    character(len=:), allocatable :: whole, blocked
    integer :: d, f, b
    logical :: every_size
    every_size = long_checks()
    do d = 1, size(decks)
      do f = 1, 10
        if (.not. every_size .and. mod(d + f, 2) /= 0) cycle
        options = run_options_t()
        select case (f)
        case (1)
          options%format = format_table
        case (2)
          options%format = format_table
          options%lang = lang_ru
        case (3)
          options%format = format_csv
        case (4)
          options%format = format_csv
          options%kinematics = .true.
        case (5)
          options%format = format_json
        case (6)
          options%format = format_json
          options%kinematics = .true.
        case (7)
          options%format = format_summary
        case (8)
          options%format = format_table
          options%link_frame = .true.
        case (9)
          ! the shaking block after the layout's sections (PR 3050's second one)
          options%format = format_table
          options%shaking = .true.
        case default
          options%format = format_csv
          options%shaking = .true.
        end select
        call run_one(trim(decks(d)), options, whole)
        do b = 1, size(block_sizes)
          if (.not. every_size .and. b /= mod((d + f) / 2, size(block_sizes)) + 1) cycle
          options%block_rows = block_sizes(b)
          ! and the INPUT DATA echo's arrays in chunks of as many values
          options%echo_chunk = block_sizes(b)
          call run_one(trim(decks(d)), options, blocked)
          call check_true(t, "blocks: "//trim(decks(d))//" format case "//int_str(f)//", blocks of "// &
            int_str(block_sizes(b))//" rows = one block", blocked == whole, first_difference(whole, blocked))
        end do
      end do
    end do
  end subroutine test_blocks_equal_whole

  !> The drawings keep only the rows they draw, block by block (kinetostat_row_keeper): the
  !> SVG sheet, --at K (the mechanism, its plans, DXF, JSON --plans) at the first, a middle
  !> and the last step, in blocks of 1 and 7 rows (one of them in turn without `tools/test
  !> --long`), equal the one-block run byte for byte; and a long run's sheet (5001 steps: the
  !> extremes per bucket) in blocks of 777 (and 4000 with --long).
  subroutine test_drawings_in_blocks(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: drawn(*) = [character(len=30) :: "data/pr3207.nml", "data/assur_pr3050.nml", &
      "data/linkage_slider_crank.nml", "data/class3.nml"]
    integer, parameter :: sizes(*) = [1, 7]
    !> The drawings tried: format and --at K (0: the sheet of the whole run).
    integer, parameter :: formats(*) = [format_svg, format_svg, format_plans, format_dxf, format_json]
    integer, parameter :: steps_drawn(*) = [0, 7, 13, 1, 7]
    !> Blocks of the long run.
    integer, parameter :: long_blocks(2) = [777, 4000]
    type(run_options_t) :: options
    character(len=:), allocatable :: whole, blocked, long_deck
    integer :: d, f, b
    do d = 1, size(drawn)
      do f = 1, size(formats)
        options = run_options_t()
        options%format = formats(f)
        options%plans = formats(f) == format_json
        options%at_step = steps_drawn(f)
        call run_one(trim(drawn(d)), options, whole)
        do b = 1, size(sizes)
          ! without tools/test --long one of the sizes in turn
          if (.not. long_checks() .and. b /= mod(d + f, size(sizes)) + 1) cycle
          options%block_rows = sizes(b)
          call run_one(trim(drawn(d)), options, blocked)
          call check_true(t, "blocks: "//trim(drawn(d))//" drawing case "//int_str(f)//" (--at "// &
            int_str(steps_drawn(f))//"), blocks of "//int_str(sizes(b))//" rows = one block", blocked == whole, &
            first_difference(whole, blocked))
        end do
      end do
    end do
    ! a long run (5001 steps > 4096): the sheet through each bucket's extremes
    long_deck = scratch_path("long", ".nml")
    call write_long_deck(long_deck)
    options = run_options_t()
    options%format = format_svg
    call run_one(long_deck, options, whole)
    call check_true(t, "blocks: a 5001-step sheet is drawn", index(whole, 'data-steps="5001"') > 0, &
      whole(1:min(300, len(whole))))
    do b = 1, merge(2, 1, long_checks())
      options%block_rows = long_blocks(b)
      call run_one(long_deck, options, blocked)
      call check_true(t, "blocks: the 5001-step sheet in blocks of "//int_str(options%block_rows)//" = one block", &
        blocked == whole, first_difference(whole, blocked))
    end do
    open (newunit=d, file=long_deck, status="old")
    close (d, status="delete")
  contains
    !> data/pr3207.nml at 5001 steps.
    subroutine write_long_deck(path)
      character(*), intent(in) :: path
      type(deck_source_t) :: source
      type(error_t), allocatable :: error
      integer :: unit, i
      call load_deck("data/pr3207.nml", source, error)
      open (newunit=unit, file=path, status="replace", action="write")
      do i = 1, size(source%records)
        if (trim(source%records(i)) == "/") write (unit, '(a)') "  dphi = 0.072, n = 5001"
        write (unit, '(a)') trim(source%records(i))
      end do
      close (unit)
    end subroutine write_long_deck
  end subroutine test_drawings_in_blocks

  !> The spool with a bound of 100 bytes: the text goes through its file (also the second
  !> section of a layout, PR 3050's) and the target gets all of it; a run that fails after
  !> the spool took text leaves no target and no temporary file.
  subroutine test_spool(t)
    type(test_counts_t), intent(inout) :: t
    type(run_options_t) :: options
    type(spool_t) :: spool
    type(text_buffer_t) :: rest
    type(error_t), allocatable :: error
    character(len=:), allocatable :: whole, whole_report, kept, report, target, text
    character(len=*), parameter :: spool_decks(*) = [character(len=30) :: "data/pr3207.nml", "data/pr3050.nml", &
      "data/assur_sixbar_friction.nml"]
    integer, parameter :: spool_formats(*) = [format_table, format_csv, format_json]
    integer :: d, f, unit, ios
    logical :: exists
    target = scratch_path("spool", ".out")
    do d = 1, size(spool_decks)
      do f = 1, size(spool_formats)
        options = run_options_t()
        options%format = spool_formats(f)
        call run_one(trim(spool_decks(d)), options, whole, report=whole_report)
        options%block_rows = 2
        options%echo_chunk = 1
        spool = spool_t()
        spool%bound = 100
        call spool%aim(target)
        call run_one(trim(spool_decks(d)), options, kept, spool, report)
        call check_true(t, "spool: "//trim(spool_decks(d))//" went through the file", spool%spilled, "no temporary file was used")
        call check_true(t, "spool: "//trim(spool_decks(d))//" same report", report == whole_report, report)
        rest = text_buffer_t()
        call rest%append(kept)
        call spool%commit(rest, error)
        call check_true(t, "spool: "//trim(spool_decks(d))//" committed", .not. allocated(error), "commit failed")
        text = read_file(target)
        call check_true(t, "spool: "//trim(spool_decks(d))//" format "//int_str(f)//" target = one-block output", &
          text == whole, first_difference(whole, text))
        call check_true(t, "spool: the temporary lay beside "//target, allocated(spool%file), "no name")
        if (allocated(spool%file)) then
          call check_true(t, "spool: temporary named "//target//".tmp.*", index(spool%file, target//".tmp.") == 1, &
            spool%file)
          inquire (file=spool%file, exist=exists)
          call check_true(t, "spool: no temporary file left beside "//target, .not. exists, spool%file//" left")
        end if
      end do
    end do
    open (newunit=unit, file=target, status="old", iostat=ios)
    if (ios == 0) close (unit, status="delete", iostat=ios)
    call check_true(t, "spool: the target can be removed", ios == 0, target)
    ! a run failing at step 2 after the spool took step 1's text: no target, no temporary file
    options = run_options_t()
    options%format = format_csv
    options%block_rows = 1
    spool = spool_t()
    spool%bound = 10
    call spool%aim(target)
    call run_one("data/assur_toggle.nml", options, text, spool)
    call check_true(t, "spool: the failing run fails", index(text, "error 3:") == 1, text)
    inquire (file=target, exist=exists)
    call check_true(t, "spool: a failed run leaves no target", .not. exists, target//" exists")
    call check_true(t, "spool: the failing run had a temporary", allocated(spool%file), "no name")
    if (allocated(spool%file)) then
      inquire (file=spool%file, exist=exists)
      call check_true(t, "spool: a failed run leaves no temporary file", .not. exists, spool%file//" left")
    end if
  end subroutine test_spool

  !> The whole content of a file ("" when it cannot be read).
  function read_file(path) result(text)
    character(*), intent(in) :: path
    character(len=:), allocatable :: text
    integer :: unit, ios, length
    text = ""
    open (newunit=unit, file=path, access="stream", form="unformatted", action="read", status="old", iostat=ios)
    if (ios /= 0) return
    inquire (unit=unit, size=length)
    deallocate (text)
    allocate (character(len=length) :: text)
    read (unit, iostat=ios) text
    if (ios /= 0) text = ""
    close (unit)
  end function read_file

  !> Where two texts first differ, for a failure message.
  function first_difference(expected, computed) result(detail)
    character(*), intent(in) :: expected, computed
    character(len=:), allocatable :: detail
    integer :: i
    do i = 1, min(len(expected), len(computed))
      if (expected(i:i) /= computed(i:i)) exit
    end do
    detail = "first difference at byte "//int_str(i)//" of "//int_str(len(expected))//" (computed "// &
      int_str(len(computed))//"): expected '"//expected(max(1, i - 40):min(len(expected), i + 40))// &
      "' computed '"//computed(max(1, i - 40):min(len(computed), i + 40))//"'"
  end function first_difference

end module test_blocks
