!> Minimal test helpers: checks that print expected vs computed on failure and count.
module test_harness
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use kinetostat_kinds, only: wp
  use kinetostat_posix, only: process_id
  use kinetostat_text, only: int_str
  implicit none
  private
  public :: test_counts_t, check_close, check_true, report_counts, operator(.dot.), scratch_path, long_checks
  public :: next, hex

  !> Pass/fail counters.
  type :: test_counts_t
    integer :: passed = 0
    integer :: failed = 0
  end type test_counts_t

  !> Dot product as an operator, for compact test expressions.
  interface operator(.dot.)
    module procedure dot2
  end interface

contains

  pure real(wp) function dot2(a, b)
    real(wp), intent(in) :: a(:), b(:)
    dot2 = dot_product(a, b)
  end function dot2

  !> Pass when |computed - expected| <= atol + rtol*|expected| (and neither is NaN).
  subroutine check_close(t, name, expected, computed, rtol, atol)
    type(test_counts_t), intent(inout) :: t
    !> Test name printed on failure.
    character(*), intent(in) :: name
    real(wp), intent(in) :: expected, computed
    !> Relative tolerance.
    real(wp), intent(in) :: rtol
    !> Absolute tolerance (guards zero references).
    real(wp), intent(in) :: atol
    if (.not. (ieee_is_nan(expected) .or. ieee_is_nan(computed)) .and. &
        abs(computed - expected) <= atol + rtol * abs(expected)) then
      t%passed = t%passed + 1
    else
      t%failed = t%failed + 1
      write (*, '(a,a,a,es24.16,a,es24.16,a,es9.2,a,es9.2,a)') "FAIL ", name, ": expected ", expected, &
        ", computed ", computed, " (rtol ", rtol, ", atol ", atol, ")"
    end if
  end subroutine check_close

  !> Pass when `condition` holds; `detail` is printed on failure.
  subroutine check_true(t, name, condition, detail)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name
    logical, intent(in) :: condition
    character(*), intent(in) :: detail
    if (condition) then
      t%passed = t%passed + 1
    else
      t%failed = t%failed + 1
      write (*, '(a)') "FAIL "//name//": "//detail
    end if
  end subroutine check_true

  !> Final line of the Fortran tests.
  subroutine report_counts(t)
    type(test_counts_t), intent(in) :: t
    write (*, '(a,i0,a,i0,a)') "fortran: ", t%passed, " passed, ", t%failed, " failed"
  end subroutine report_counts

  !> A scratch file's path of this test process: $TMPDIR (tools/test gives its own temporary
  !> directory; /tmp when unset) / kinetostat-test-STEM-PID SUFFIX, so that two runs at once
  !> never write the same file.
  function scratch_path(stem, suffix) result(path)
    character(*), intent(in) :: stem   !< what the file is for
    character(*), intent(in) :: suffix !< its ending, e.g. ".nml"
    character(len=:), allocatable :: path
    character(len=4096) :: dir
    integer :: length, status
    call get_environment_variable("TMPDIR", dir, length, status)
    if (status /= 0 .or. length == 0) then
      dir = "/tmp"
      length = 4
    end if
    path = dir(:length)//"/kinetostat-test-"//stem//"-"//int_str(process_id())//suffix
  end function scratch_path

  !> Whether the heavy checks run in full: `tools/test --long` exports KINETOSTAT_LONG=1; without
  !> it a suite runs a fixed sample of the same checks (each kind of check still runs).
  logical function long_checks()
    character(len=8) :: value
    integer :: length, status
    call get_environment_variable("KINETOSTAT_LONG", value, length, status)
    long_checks = status == 0 .and. value == "1"
  end function long_checks

  !> xorshift64 (Marsaglia): shifts and exclusive ors only, so no signed overflow (which an
  !> optimising build may assume away) and the same sequence in every build.
  function next(state) result(z)
    !> The generator's state (not 0), advanced.
    integer(int64), intent(inout) :: state
    integer(int64) :: z
    state = ieor(state, shiftl(state, 13))
    state = ieor(state, shiftr(state, 7))
    state = ieor(state, shiftl(state, 17))
    z = state
  end function next

  !> The bits of x in hex (a failing value can be reproduced exactly).
  function hex(x) result(text)
    !> The value.
    real(wp), intent(in) :: x
    character(len=18) :: text
    write (text, '("z",z16.16)') transfer(x, 1_int64)
  end function hex
end module test_harness
