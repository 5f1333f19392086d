!> Unit tests of the output side: the step table, the output policy (fields never `*`,
!> exponent form when too wide), and every writer (CSV, legacy table frame, JSON), and the
!> finite guard of the run pipeline.
module test_io
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force, col_force_angle, col_flag, col_count
  use kinetostat_format, only: fixed_field, exp_field, int_field, full_number, whole_number, echo_number, &
    display_width, pad_right
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_csv_writer, only: write_csv
  use kinetostat_json_writer, only: write_json, json_string
  use kinetostat_npy_writer, only: write_npy, npy_header
  use kinetostat_run, only: guard_finite
  use kinetostat_diff, only: diff_options_t, diff_outputs, diff_same, diff_different
  use kinetostat_step_table, only: column_t
  use test_harness, only: test_counts_t, check_true
  implicit none
  private
  public :: run_io_tests

contains

  subroutine run_io_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_fields(t)
    call test_step_table(t)
    call test_csv(t)
    call test_json(t)
    call test_npy(t)
    call test_guard(t)
    call test_diff(t)
  end subroutine run_io_tests

  !> kinetostat_diff on crafted CSV and table pairs: angles modulo 360, the angle of a
  !> vanishing force ignored, a real difference reported, not comparable pairs rejected.
  subroutine test_diff(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: header = "phi1,F16,F16G,M1"
    type(column_t) :: catalog(0)
    type(diff_options_t) :: options
    type(text_buffer_t) :: report
    type(error_t), allocatable :: error
    integer :: status
    character(len=60) :: a(3), b(3)
    a = [character(len=60) :: header, "0,1.0E+2,3.59999E+2,5.0", "30,0.0E+0,0.0E+0,1.0"]
    b = [character(len=60) :: header, "0,1.0E+2,1.0E-3,5.0", "30,0.0E+0,1.234E+2,1.0"]
    options%atol = 0.005_wp
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: 359.999 vs 0.001 deg and a vanishing force's angle are the same", &
      .not. allocated(error) .and. status == diff_same, report%text())
    options = diff_options_t()
    report = text_buffer_t()
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: 0.002 deg is beyond the default angle tolerance", status == diff_different .and. &
      index(report%text(), "step 1, column F16G: 3.59999E+2 vs 1.0E-3 (diff 2.0e-03 deg)") == 1, report%text())
    b(2) = "0,1.0E+2,3.59999E+2,5.1"
    report = text_buffer_t()
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: a real difference is named", status == diff_different .and. &
      index(report%text(), "step 1, column M1: 5.0 vs 5.1 (rel 2.0e-02)") == 1, report%text())
    b(1) = "phi1,F21,F21G,M1"
    report = text_buffer_t()
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: other columns are listed and differ", .not. allocated(error) .and. &
      status == diff_different .and. index(report%text(), "columns only in a: F16, F16G") == 1 .and. &
      index(report%text(), "columns only in b: F21, F21G") > 0, report%text())
    ! the same columns in another order are the same file
    b = [character(len=60) :: "M1,F16G,phi1,F16", "5.0,3.59999E+2,0,1.0E+2", "1.0,0.0E+0,30,0.0E+0"]
    report = text_buffer_t()
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: columns in another order are matched by name", .not. allocated(error) .and. &
      status == diff_same, report%text())
    b(1) = "x,y,z,w"
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: no column in common is an error", allocated(error), "no error")
    a(1) = " KINETOSTAT  X"
    call diff_outputs("a", a, "b", b, catalog, options, report, status, error)
    call check_true(t, "diff: a table and a CSV file are not comparable", allocated(error), "no error")
  end subroutine test_diff

  !> Expect `computed` to equal `expected` exactly, printing both on failure.
  subroutine check_text(t, name, expected, computed)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name, expected, computed
    call check_true(t, name, expected == computed, "expected '"//expected//"', computed '"//computed//"'")
  end subroutine check_text

  subroutine test_fields(t)
    type(test_counts_t), intent(inout) :: t
    real(wp) :: x
    integer :: e
    character(len=12) :: f
    call check_text(t, "fixed_field fits", "     2741.19", fixed_field(2741.19_wp, 12, 2))
    call check_text(t, "fixed_field negative zero", "        0.00", fixed_field(-0.0_wp, 12, 2))
    ! 123456789.00 takes all 12 characters: it would run into the previous field
    call check_text(t, "fixed_field too wide -> exponent", "  1.2346E+08", fixed_field(123456789.0_wp, 12, 2))
    call check_text(t, "fixed_field 1e300", "  1.00E+300", fixed_field(1.0e300_wp, 11, 2))
    ! a value that rounds to zero prints as 0.00, never -0.00
    call check_text(t, "fixed_field -1e-300 rounds to 0.00", "       0.00", fixed_field(-1.0e-300_wp, 11, 2))
    call check_text(t, "fixed_field -0.0049 rounds to 0.00", "       0.00", fixed_field(-0.0049_wp, 11, 2))
    call check_text(t, "fixed_field -0.0051 is -0.01", "      -0.01", fixed_field(-0.0051_wp, 11, 2))
    call check_text(t, "fixed_field -4e-14 with 3 decimals", "      0.000", fixed_field(-4.0e-14_wp, 11, 3))
    call check_text(t, "fixed_field -1e300", " -1.00E+300", fixed_field(-1.0e300_wp, 11, 2))
    call check_text(t, "exp_field legacy E", "   0.274E+04", exp_field(2741.19_wp, 12, 3))
    call check_text(t, "exp_field keeps E for 3-digit exponents", "  0.100E+301", exp_field(1.0e300_wp, 12, 3))
    call check_text(t, "int_field", " -1", int_field(-1.0_wp, 3))
    call check_text(t, "full_number", "2.741190000000E+003", full_number(2741.19_wp))
    call check_text(t, "full_number minus zero", "0.000000000000E+000", full_number(-0.0_wp))
    call check_text(t, "whole_number", "1", whole_number(1.0_wp))
    call check_text(t, "whole_number of a fraction", "1.500000000000E+000", whole_number(1.5_wp))
    call check_text(t, "echo_number 3-digit exponent keeps E", " -1.000000000E+300", echo_number(-1.0e300_wp))
    call check_true(t, "display_width Cyrillic", display_width("ИСХОДНЫЕ") == 8, "UTF-8 letters count once")
    call check_true(t, "pad_right Cyrillic", display_width(pad_right("Н*м", 6)) == 6, "padded to 6 columns")
    ! no '*' in any field over the whole exponent range, at every width the tables use
    do e = -308, 308, 7
      x = -7.123456789_wp * 10.0_wp**e
      f = fixed_field(x, 12, 2)
      call check_true(t, "fixed_field no star 1e"//trim(itoa(e)), index(f, "*") == 0 .and. f(1:1) == " ", &
                      "got '"//f//"'")
      call check_true(t, "fixed_field width 9 1e"//trim(itoa(e)), index(fixed_field(x, 9, 2), "*") == 0, &
                      "got '"//fixed_field(x, 9, 2)//"'")
      call check_true(t, "exp_field no star 1e"//trim(itoa(e)), index(exp_field(x, 12, 3), "*") == 0, &
                      "got '"//exp_field(x, 12, 3)//"'")
    end do
  end subroutine test_fields

  function itoa(i) result(s)
    integer, intent(in) :: i
    character(len=12) :: s
    write (s, '(i0)') i
  end function itoa

  !> A small table: two rows, an angle, a force with its angle, a flag, a count.
  function sample_table() result(table)
    type(step_table_t) :: table
    table%mechanism = "demo"
    table%deck = 'dir/"quoted".nml'
    table%row_name = "step"
    table%driver = "M1"
    call table%add_column("phi1", "deg", col_input_angle)
    call table%add_column("F16", "N", col_force)
    call table%add_column("F16G", "deg", col_force_angle)
    call table%add_column("JAM", "", col_flag)
    call table%add_column("z1", "", col_count)
    call table%add_column("hidden", "m", col_force, csv=.false.)
    table%input_column = 1
    call table%allocate_rows(2)
    table%rows(:, 1) = [0.0_wp, 2741.19_wp, 180.0_wp, 0.0_wp, 20.0_wp, 1.0_wp]
    table%rows(:, 2) = [30.0_wp, -0.0_wp, 0.0_wp, 1.0_wp, 40.0_wp, 2.0_wp]
    call table%echo_real("L_AB", 0.11_wp, "m")
    call table%echo_array("F5C", [1.0_wp, 2.0_wp], "N")
  end function sample_table

  subroutine test_step_table(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    integer :: i
    table = sample_table()
    call check_true(t, "step table column_index", table%column_index("F16G") == 3, "F16G is column 3")
    call check_true(t, "step table column_index unknown", table%column_index("nope") == 0, "0 when absent")
    call check_true(t, "step table rows", table%row_count() == 2, "two rows")
    call check_true(t, "step table echo count", table%echo_count == 2, "two records")
    do i = 1, 40
      call table%echo_real("X", real(i, wp), "")
    end do
    call check_true(t, "step table echo grows", table%echo_count == 42 .and. table%echo(42)%values(1) == 40.0_wp, &
                    "42 records, the last 40")
    call test_echo_runs(t)
  end subroutine test_step_table

  !> An echoed array kept as runs of equal values gives back exactly its values (bits: -0,
  !> subnormals, NaN), however it is cut into chunks; an array without runs is kept as it is.
  subroutine test_echo_runs(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    real(wp), allocatable :: v(:), got(:)
    real(wp) :: u
    integer :: trial, n, i, first, last, bad
    logical :: kept_as_runs, kept_plain
    bad = 0
    kept_as_runs = .false.
    kept_plain = .false.
    do trial = 1, 300
      call random_number(u)
      n = int(u * 200.0_wp)
      allocate (v(n))
      do i = 1, n
        call random_number(u)
        if (i > 1 .and. u < 0.8_wp * real(mod(trial, 3), wp) / 2.0_wp) then
          v(i) = v(i - 1)
        else
          call random_number(u)
          select case (int(u * 5.0_wp))
          case (0)
            v(i) = -0.0_wp
          case (1)
            v(i) = 0.0_wp
          case (2)
            v(i) = tiny(1.0_wp) * u
          case (3)
            v(i) = ieee_value(1.0_wp, ieee_quiet_nan)
          case default
            v(i) = real(int(u * 10.0_wp), wp)
          end select
        end if
      end do
      table = step_table_t()
      call table%echo_array("A", v, "")
      if (allocated(table%echo(1)%run_end)) kept_as_runs = .true.
      if (.not. allocated(table%echo(1)%run_end)) kept_plain = .true.
      if (table%echo(1)%value_count() /= n) bad = bad + 1
      do i = 1, 5
        call random_number(u)
        first = 1 + int(u * n)
        call random_number(u)
        last = min(n, first + int(u * n))
        if (n == 0) cycle
        allocate (got(last - first + 1))
        call table%echo(1)%get_values(first, last, got)
        if (any(transfer(got, 0_int64, size(got)) /= transfer(v(first:last), 0_int64, size(got)))) bad = bad + 1
        deallocate (got)
      end do
      deallocate (v)
    end do
    call check_true(t, "echo arrays as runs: values back bit for bit (300 arrays, 5 slices each)", bad == 0, &
      int_str(bad)//" slices or counts differ")
    call check_true(t, "echo arrays: both ways of keeping them were tried", kept_as_runs .and. kept_plain, &
      "runs tried: "//merge("yes", "no ", kept_as_runs)//", plain tried: "//merge("yes", "no ", kept_plain))
    table = step_table_t()
    call table%echo_array("F5", [(1000.0_wp, i=1, 100000)], "N")
    call check_true(t, "echo arrays: 10^5 equal values are one run", size(table%echo(1)%values) == 1, &
      "kept "//int_str(size(table%echo(1)%values))//" values")
  end subroutine test_echo_runs

  subroutine test_csv(t)
    type(test_counts_t), intent(inout) :: t
    type(text_buffer_t) :: out
    character(len=*), parameter :: nl = new_line("a")
    call write_csv(sample_table(), out)
    call check_text(t, "csv writer", "phi1,F16,F16G,JAM,z1"//nl// &
      "0.000000000000E+000,2.741190000000E+003,1.800000000000E+002,0,20"//nl// &
      "3.000000000000E+001,0.000000000000E+000,0.000000000000E+000,1,40"//nl, out%text())
  end subroutine test_csv

  subroutine test_json(t)
    type(test_counts_t), intent(inout) :: t
    type(text_buffer_t) :: out
    character(len=:), allocatable :: text
    call write_json("DEMO TITLE", sample_table(), out)
    text = out%text()
    call check_true(t, "json escapes the deck path", index(text, '"deck": "dir/\"quoted\".nml"') > 0, text)
    call check_true(t, "json rows", index(text, "[3.000000000000E+001, 0.000000000000E+000, " // &
                    "0.000000000000E+000, 1, 40, 2.000000000000E+000]") > 0, text)
    call check_true(t, "json hidden column listed", index(text, '"name": "hidden", "unit": "m", "kind": "force", ' // &
                    '"csv": false}') > 0, text)
    call check_true(t, "json array echo", index(text, '{"name": "F5C", "value": [1.000000000000E+000, ' // &
                    '2.000000000000E+000], "unit": "N"}') > 0, text)
    call check_text(t, "json_string control characters", '"a\tb\\c\n\u0001\u00FF\""', &
      json_string("a"//achar(9)//"b\c"//achar(10)//achar(1)//char(255)//'"'))
  end subroutine test_json

  !> The npy writer on the small table (hand-made bytes: header and two records of the CSV's
  !> five columns), a header of a name with UTF-8 letters (version 3.0), a quote and a
  !> backslash (escaped for Python's literal parser).
  subroutine test_npy(t)
    type(test_counts_t), intent(inout) :: t
    type(text_buffer_t) :: out
    type(step_table_t) :: table
    type(error_t), allocatable :: error
    character(len=:), allocatable :: text, dict
    character(len=8) :: b
    real(wp), parameter :: row2(5) = [30.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 40.0_wp]
    integer :: i
    logical :: same
    table = sample_table()
    table%total_rows = 2
    call write_npy(table, out, error)
    text = out%text()
    dict = "{'descr': [('phi1', '<f8'), ('F16', '<f8'), ('F16G', '<f8'), ('JAM', '<f8'), ('z1', '<f8')], " // &
      "'fortran_order': False, 'shape': (2,), }"
    call check_true(t, "npy header: magic, version 1.0, length, dictionary, 64-byte aligned", &
      text(1:10) == char(147)//"NUMPY"//char(1)//char(0)//char(182)//char(0) .and. &
      text(11:10 + len(dict)) == dict .and. text(192:192) == achar(10) .and. &
      verify(text(11 + len(dict):191), " ") == 0 .and. .not. allocated(error), text(1:min(len(text), 192)))
    same = len(text) == 192 + 2 * 5 * 8
    do i = 1, 5
      b = transfer(row2(i), b)
      if (same) same = same .and. text(192 + 40 + 8 * (i - 1) + 1:192 + 40 + 8 * i) == b
    end do
    call check_true(t, "npy records: 2 x 5 float64, -0 written as 0, the JSON-only column left out", same, &
      "length "//itoa(len(text))//", expected "//itoa(192 + 80))
    text = npy_header([character(len=4) :: "Fб", "a'b\"], [3, 4], 7)
    call check_true(t, "npy header of UTF-8 names: version 3.0, 4-byte length, quote and backslash escaped", &
      text(7:8) == achar(3)//achar(0) .and. mod(len(text), 64) == 0 .and. &
      index(text, "[('Fб', '<f8'), ('a\'b\\', '<f8')]") > 0 .and. &
      index(text, "'shape': (7,)") > 0, text)
  end subroutine test_npy

  subroutine test_guard(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(error_t), allocatable :: error
    table = sample_table()
    call guard_finite(table, error)
    call check_true(t, "guard passes finite results", .not. allocated(error), "no error")
    table%rows(2, 2) = ieee_value(1.0_wp, ieee_quiet_nan)
    call guard_finite(table, error)
    call check_true(t, "guard rejects NaN", allocated(error), "an error")
    if (allocated(error)) then
      call check_true(t, "guard exit 3", error%code == exit_geometry, "code 3")
      call check_text(t, "guard message", 'dir/"quoted".nml: &demo: step 2 (phi1 = 30 deg): F16 is not finite ' // &
        "(overflow: the deck's magnitudes are out of the representable range)", error%message)
    end if
    table = sample_table()
    table%run_tally%residual%value = ieee_value(1.0_wp, ieee_positive_inf)
    call guard_finite(table, error)
    call check_true(t, "guard rejects an infinite self-check figure", allocated(error), "an error")
  end subroutine test_guard

end module test_io
