!> The row writer of CSV cells and JSON numbers (kinetostat_decimal's put_cell_numbers)
!> against the same cells written one at a time the way every cell was before it
!> (`one_cell`: the whole-number rule, then put_es_compact's ES20.12E3), byte for byte, and
!> against the compiler's formatted WRITE: rows of 64 doubles of ten families (any bit
!> pattern, subnormals, 13-digit decimal ties nudged by up to 3 ulp, 13-digit decimals,
!> powers of ten and the numbers just below them that round up to them, powers of two,
!> magnitudes 1e-14 .. 1e16 uniform in the logarithm, products of 10**13 at the writer's
!> change of scale, whole and half numbers, zeros), both signs, joined by "," and by ", ",
!> every seventh column one of whole numbers: 3.2 * 10^4 values (10^7 with `tools/test
!> --long`; a fixed seed, the first rows the same in both); and the same rows, four at a
!> time, as whole lines framed as the JSON's.
!> The reference writers fill a caller's buffer as the writer under test does, so their
!> character(*) buffers are intent(inout) by design.
! allow(assumed-size-character-intent)
module test_cells
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp
  use kinetostat_decimal, only: put_cell_numbers, put_es_compact, put_whole
  use kinetostat_text, only: int_str
  use test_harness, only: test_counts_t, check_true, long_checks, next, hex
  implicit none
  private
  public :: run_cells_tests

  !> Values a row.
  integer, parameter :: row_length = 64
  !> Rows of the default run and of `tools/test --long`.
  integer, parameter :: sample_rows = 500, long_rows = 156250
  !> Every how many values one is also checked against the compiler's WRITE (default, --long).
  integer, parameter :: write_every = 1, long_write_every = 97
  !> Mismatches printed at most.
  integer, parameter :: max_shown = 5
  !> Rows a block of put_cell_numbers (lines framed as the JSON's rows).
  integer, parameter :: block_rows = 4
  !> The framing of a JSON row (put_cell_numbers' opening and closing).
  character(*), parameter :: json_opening = "    [", json_closing = "],"

contains

  subroutine run_cells_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_rows(t)
    call test_room(t)
    call test_lines_room(t)
  end subroutine run_cells_tests

  !> Rows of every family through put_cell_numbers against one_cell and the WRITE.
  subroutine test_rows(t)
    type(test_counts_t), intent(inout) :: t
    real(wp) :: row(row_length)
    integer :: columns(row_length)
    logical :: whole(row_length)
    character(len=row_length * 32) :: mine, theirs
    character(len=block_rows * (row_length * 32 + 16)) :: lines, expected_lines
    real(wp) :: block(row_length, block_rows)
    character(len=32) :: cell, written
    character(len=:), allocatable :: separator, shown
    integer(int64) :: state
    integer :: n_rows, every, r, i, pos, expected, bad, bad_write, n_values, bad_lines, n_lines, n_expected_lines
    n_rows = merge(long_rows, sample_rows, long_checks())
    every = merge(long_write_every, write_every, long_checks())
    do i = 1, row_length
      columns(i) = mod(37 * i, row_length) + 1   ! every value once, out of order
      whole(i) = mod(i, 7) == 3
    end do
    state = 20261129_int64
    bad = 0
    bad_write = 0
    bad_lines = 0
    n_values = 0
    n_expected_lines = 0
    allocate (character(len=0) :: shown)
    do r = 1, n_rows
      do i = 1, row_length
        row(i) = sample(state, (r - 1) * row_length + i)
      end do
      if (mod(r, 2) == 0) then
        separator = ", "
      else
        separator = ","
      end if
      ! the row as the cells were written before, one at a time
      call one_row(row, columns, whole, separator, theirs, expected)
      do i = 1, row_length
        n_values = n_values + 1
        if (mod(n_values, every) == 0 .and. .not. whole(i)) then
          pos = 0
          call one_cell(row(columns(i)), .false., cell, pos)
          write (written, '(es20.12e3)') row(columns(i)) + 0.0_wp
          if (cell(1:pos) /= trim(adjustl(written))) then
            bad_write = bad_write + 1
            if (bad_write <= max_shown) shown = shown//" [WRITE "//hex(row(columns(i)))//" '"//cell(1:pos)// &
              "' vs '"//trim(adjustl(written))//"']"
          end if
        end if
      end do
      pos = 0
      if (mod(r, 3) == 0) then
        ! the form without whole columns: every cell a full number
        call one_row(row, columns, spread(.false., 1, row_length), separator, theirs, expected)
        call put_cell_numbers(row, row_length, 1, columns, "", separator, "", mine, pos)
      else
        call put_cell_numbers(row, row_length, 1, columns, "", separator, "", mine, pos, whole)
      end if
      if (pos /= expected .or. mine(1:pos) /= theirs(1:expected)) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" [row "//int_str(r)//": "//first_difference(mine(1:pos), theirs(1:expected), &
          row, columns)//"]"
      end if
      ! a block of rows as whole lines (put_cell_numbers, the JSON's framing), every separator ", "
      block(:, mod(r - 1, block_rows) + 1) = row
      call one_row(row, columns, whole, ", ", theirs, expected)
      expected_lines(n_expected_lines + 1:n_expected_lines + len(json_opening) + expected + len(json_closing) + 1) = &
        json_opening//theirs(1:expected)//json_closing//new_line("a")
      n_expected_lines = n_expected_lines + len(json_opening) + expected + len(json_closing) + 1
      if (mod(r, block_rows) == 0) then
        n_lines = 0
        call put_cell_numbers(block, row_length, block_rows, columns, json_opening, ", ", json_closing//new_line("a"), &
          lines, n_lines, whole)
        if (n_lines /= n_expected_lines .or. lines(1:n_lines) /= expected_lines(1:n_expected_lines)) then
          bad_lines = bad_lines + 1
          if (bad_lines <= max_shown) shown = shown//" [lines of rows "//int_str(r - block_rows + 1)//" .. "// &
            int_str(r)//": "//int_str(n_lines)//" vs "//int_str(n_expected_lines)//" characters]"
        end if
        n_expected_lines = 0
      end if
    end do
    call check_true(t, "cells: "//int_str(n_rows * row_length)//" values in rows equal the cells written one at a time", &
      bad == 0, "rows differ "//int_str(bad)//":"//shown)
    call check_true(t, "cells: "//int_str(n_rows / block_rows)//" blocks of "//int_str(block_rows)// &
      " rows as framed lines equal the rows written one at a time", bad_lines == 0, &
      "blocks differ "//int_str(bad_lines)//":"//shown)
    call check_true(t, "cells: every "//int_str(every)//"th full number equals the compiler's ES20.12E3", bad_write == 0, &
      "mismatches "//int_str(bad_write)//":"//shown)
  end subroutine test_rows

  !> The writer stores at most 8 characters past a row's text (the room its callers make)
  !> and never before it.
  subroutine test_room(t)
    type(test_counts_t), intent(inout) :: t
    character(len=200) :: buf
    real(wp) :: row(4)
    integer :: pos, i
    logical :: ok
    row = [-1.234567890123456e-5_wp, 0.0_wp, 7.0_wp, -9.87654321e12_wp]
    buf = repeat("#", len(buf))
    pos = 10
    call put_cell_numbers(row, 4, 1, [(i, i = 1, 4)], "", ",", "", buf, pos, [.false., .false., .true., .false.])
    ok = buf(1:10) == repeat("#", 10) .and. buf(pos + 9:) == repeat("#", len(buf) - pos - 8) .and. &
      buf(11:pos) == "-1.234567890123E-005,0.000000000000E+000,7,-9.876543210000E+012"
    call check_true(t, "cells: a row's text in place, at most 8 characters stored past it", ok, "'"//buf(1:pos + 9)//"'")
  end subroutine test_room

  !> Lines of rows (put_cell_numbers): each framed by its opening and closing, the text in
  !> place and at most 8 characters stored past it.
  subroutine test_lines_room(t)
    type(test_counts_t), intent(inout) :: t
    character(len=200) :: buf
    real(wp) :: rows(3, 2)
    integer :: pos
    logical :: ok
    rows = reshape([1.5_wp, -2.0_wp, 0.25_wp, 3.0e-11_wp, 4.0_wp, -0.0_wp], [3, 2])
    buf = repeat("#", len(buf))
    pos = 3
    call put_cell_numbers(rows, 3, 2, [3, 1], "[", ", ", "]"//new_line("a"), buf, pos)
    ok = buf(1:3) == "###" .and. buf(pos + 9:) == repeat("#", len(buf) - pos - 8) .and. &
      buf(4:pos) == "[2.500000000000E-001, 1.500000000000E+000]"//new_line("a")// &
      "[0.000000000000E+000, 3.000000000000E-011]"//new_line("a")
    call check_true(t, "cells: rows as framed lines in place, at most 8 characters stored past them", ok, &
      "'"//buf(1:pos + 9)//"'")
  end subroutine test_lines_room

  !> One cell the way every cell was written before put_cell_numbers.
  subroutine one_cell(x, whole, buf, pos)
    real(wp), intent(in) :: x
    logical, intent(in) :: whole
    character(*), intent(inout) :: buf
    integer, intent(inout) :: pos
    if (whole) then
      if (abs(x) < 1.0e15_wp .and. x == aint(x)) then
        call put_whole(nint(x, kind=int64), buf, pos)
        return
      end if
    end if
    call put_es_compact(x + 0.0_wp, 12, 3, buf, pos)
  end subroutine one_cell

  !> A row the way rows were written before put_cell_numbers: one_cell after one_cell.
  subroutine one_row(row, columns, whole, separator, buf, pos)
    real(wp), intent(in) :: row(:)
    integer, intent(in) :: columns(:)
    logical, intent(in) :: whole(:)
    character(*), intent(in) :: separator
    character(*), intent(inout) :: buf
    integer, intent(out) :: pos
    integer :: i
    pos = 0
    do i = 1, size(columns)
      if (i > 1) then
        buf(pos + 1:pos + len(separator)) = separator
        pos = pos + len(separator)
      end if
      call one_cell(row(columns(i)), whole(i), buf, pos)
    end do
  end subroutine one_row

  !> The first differing cell of two rows, with the value's bits.
  function first_difference(mine, theirs, row, columns) result(text)
    character(*), intent(in) :: mine, theirs
    real(wp), intent(in) :: row(:)
    integer, intent(in) :: columns(:)
    character(len=:), allocatable :: text
    integer :: i, cell
    cell = 1
    do i = 1, min(len(mine), len(theirs))
      if (mine(i:i) /= theirs(i:i)) exit
      if (mine(i:i) == ",") cell = cell + 1
    end do
    text = "cell "//int_str(cell)//" "//hex(row(columns(min(cell, size(columns)))))//" at "//int_str(i)//": '"// &
      mine(max(1, i - 20):min(len(mine), i + 20))//"' vs '"//theirs(max(1, i - 20):min(len(theirs), i + 20))//"'"
  end function first_difference

  !> The i-th value: a family chosen by i, drawn from the generator, either sign.
  function sample(state, i) result(x)
    integer(int64), intent(inout) :: state
    integer, intent(in) :: i
    real(wp) :: x
    integer(int64) :: bits, digits13
    real(wp) :: u
    integer :: expo, j
    bits = next(state)
    select case (mod(i, 10))
    case (0) ! any finite bit pattern
      x = transfer(bits, x)
      if (.not. ieee_is_finite(x)) x = transfer(shiftr(bits, 12), x)
    case (1) ! subnormals and the smallest normals
      x = transfer(iand(bits, int(z'001FFFFFFFFFFFFF', int64)), x)
    case (2, 3) ! a 13-digit decimal (2: plus half a unit of its last digit, a decimal tie), nudged
      digits13 = 1000000000000_int64 + mod(shiftr(bits, 1), 9000000000000_int64)
      expo = int(mod(shiftr(next(state), 1), 30_int64)) - 26
      x = real(digits13, wp)
      if (mod(i, 10) == 2) x = x + 0.5_wp
      x = x * 10.0_wp**expo
      x = nudged(x, state, 3)
    case (4) ! a power of ten, or just below one: rounds up to it at 13 digits
      expo = int(mod(shiftr(bits, 1), 44_int64)) - 20
      x = 10.0_wp**expo
      if (btest(bits, 50)) x = x * (1.0_wp - real(mod(shiftr(next(state), 1), 100_int64), wp) * 1.0e-15_wp)
      x = nudged(x, state, 2)
    case (5) ! a power of two (a binade's first double) or a neighbour
      expo = int(mod(shiftr(bits, 1), 100_int64)) - 50
      x = nudged(2.0_wp**expo, state, 2)
    case (6) ! magnitudes of results, 1e-14 .. 1e16, uniform in the logarithm
      u = real(shiftr(bits, 11), wp) * 2.0_wp**(-53)
      x = 10.0_wp**(30.0_wp * u - 14.0_wp)
    case (7) ! |x| * 10**(12 - k) at 10**13, where the writer takes its next scale
      expo = int(mod(shiftr(bits, 1), 26_int64)) - 12
      x = 10.0_wp**expo * (1.0_wp - real(mod(shiftr(next(state), 1), 2000_int64), wp) * 2.0_wp**(-52))
    case (8) ! whole numbers and halves (the whole columns' cases), up to beyond 1e15
      x = real(mod(shiftr(bits, 1), 2000001_int64) - 1000000_int64, wp)
      j = int(mod(shiftr(next(state), 1), 5_int64))
      if (j == 1) x = x / 2.0_wp
      if (j == 2) x = x * 1.0e10_wp
      if (j == 3) x = 1.0e15_wp + real(mod(shiftr(bits, 1), 3_int64) - 1, wp)
    case default ! zeros
      x = 0.0_wp
    end select
    if (btest(bits, 7)) x = -x
  end function sample

  !> x moved by up to `most` ulp either way.
  function nudged(x, state, most) result(y)
    real(wp), intent(in) :: x
    integer(int64), intent(inout) :: state
    integer, intent(in) :: most
    real(wp) :: y
    integer :: j, steps
    y = x
    steps = int(mod(shiftr(next(state), 1), int(2 * most + 1, int64))) - most
    do j = 1, abs(steps)
      y = nearest(y, real(sign(1, steps), wp))
    end do
  end function nudged

end module test_cells
