!> Minimal test helpers: checks that print expected vs computed on failure and count.
module test_harness
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: test_counts_t, check_close, check_true, report_counts, operator(.dot.)

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

end module test_harness
