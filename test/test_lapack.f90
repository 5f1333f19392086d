!> The singular-position test of solve_dense (a cheap bound first, dgecon only near the
!> threshold) against the test as it was (dgesv, then dgecon always): the same verdict on a
!> fuzzed set of 6x6 and 3x3 systems, well-conditioned, badly scaled and near-singular ones
!> whose reciprocal condition straddles rcond_threshold (a fixed seed, so a failure repeats);
!> and solve_dense's own LU (a port of dgesv) against the library's dgesv bit for bit: the
!> factors, pivots, zero-pivot verdict and solution, on those systems and on sparse ones with
!> signed zeros, small integers (pivot ties, exact cancellations) and subnormal columns.
module test_lapack
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_lapack, only: solve_dense, singular_by_estimate, solve_by, by_dgesv, by_port, inverse_norm_bound, &
    factor_dense, solve_factored, trsm_table
  use test_harness, only: test_counts_t, check_true, long_checks
  implicit none
  private
  public :: run_lapack_tests

  !> Fuzzed systems per size and check: the first 5000 of the same fixed sequence; all 20000
  !> with `tools/test --long` (long_checks).
  integer, parameter :: sample_system_count = 5000, long_system_count = 20000
  !> Fuzzed systems per size in this run (run_lapack_tests sets it).
  integer :: system_count = sample_system_count

contains

  subroutine run_lapack_tests(t)
    type(test_counts_t), intent(inout) :: t
    system_count = merge(long_system_count, sample_system_count, long_checks())
    call fuzz(t, 6)
    call fuzz(t, 3)
    call bound_holds(t, 6)
    call bound_holds(t, 3)
    call bitwise(t, 6)
    call bitwise(t, 3)
    call bitwise(t, 2)
    call bitwise(t, 5) ! other shapes of dgetrf2's recursion (not solved by the product today)
    call bitwise(t, 8)
    call with_table(t, 15)
    call with_table(t, 12)
    call with_table(t, 6)
  end subroutine run_lapack_tests

  !> factor_dense with trsm_table(n) (as the general linkage factors its Jacobians of order
  !> 3n) gives solve_dense's verdict and dgesv's factors, pivots and solutions bit for bit.
  subroutine with_table(t, n)
    type(test_counts_t), intent(inout) :: t
    integer, intent(in) :: n
    real(wp) :: a(n, n), b(n), lu_ref(n, n), lu_own(n, n), x_ref(n), x_own(n), x_dense(n)
    integer :: ipiv_ref(n), ipiv_own(n), info_ref, table(n, n)
    type(error_t), allocatable :: err_own, err_dense
    integer(int64) :: state
    integer :: i, k, differ, first_bad
    character(len=200) :: detail
    state = 3100_int64 + n
    table = trsm_table(n)
    differ = 0
    first_bad = 0
    do i = 1, system_count
      call random_system(state, mod(i, 8), a)
      do k = 1, n
        b(k) = 2.0_wp * uniform(state) - 1.0_wp
      end do
      call solve_by(by_dgesv, a, b, lu_ref, ipiv_ref, x_ref, info_ref)
      call factor_dense(a, lu_own, ipiv_own, err_own, table)
      x_own = b
      if (.not. allocated(err_own)) call solve_factored(lu_own, ipiv_own, x_own)
      call solve_dense(a, b, x_dense, err_dense)
      if (allocated(err_own) .neqv. allocated(err_dense)) then
        differ = differ + 1
      else if (info_ref == 0) then
        if (any(ipiv_ref /= ipiv_own) .or. any(transfer(lu_ref, 0_int64, n * n) /= transfer(lu_own, 0_int64, n * n)) .or. &
            (.not. allocated(err_own) .and. (any(transfer(x_ref, 0_int64, n) /= transfer(x_own, 0_int64, n)) .or. &
            any(transfer(x_dense, 0_int64, n) /= transfer(x_own, 0_int64, n))))) differ = differ + 1
      end if
      if (differ > 0 .and. first_bad == 0) first_bad = i
    end do
    write (detail, '(a,i0,a,i0,a,i0,a)') "n = ", n, ": ", differ, " systems differ (first: system ", first_bad, ")"
    call check_true(t, "lapack: factor_dense with trsm_table = dgesv and solve_dense bit for bit", differ == 0, trim(detail))
  end subroutine with_table

  !> system_count systems of size n from every family: the port's factors, pivots, info and
  !> solution must be dgesv's bit for bit (signed zeros included).
  subroutine bitwise(t, n)
    type(test_counts_t), intent(inout) :: t
    integer, intent(in) :: n
    real(wp) :: a(n, n), b(n), lu_ref(n, n), lu_own(n, n), x_ref(n), x_own(n)
    integer :: ipiv_ref(n), ipiv_own(n), info_ref, info_own
    integer(int64) :: state
    integer :: i, k, differ, zero_pivots, first_bad
    character(len=200) :: detail
    state = 2400_int64 + n
    differ = 0
    zero_pivots = 0
    first_bad = 0
    do i = 1, system_count
      call random_system(state, mod(i, 8), a)
      do k = 1, n
        b(k) = 2.0_wp * uniform(state) - 1.0_wp
      end do
      if (mod(i, 3) == 0) b(1) = -0.0_wp
      call solve_by(by_dgesv, a, b, lu_ref, ipiv_ref, x_ref, info_ref)
      call solve_by(by_port, a, b, lu_own, ipiv_own, x_own, info_own)
      if (info_ref > 0) zero_pivots = zero_pivots + 1
      if (info_ref /= info_own .or. any(ipiv_ref /= ipiv_own) .or. &
          any(transfer(lu_ref, 0_int64, n * n) /= transfer(lu_own, 0_int64, n * n)) .or. &
          (info_ref == 0 .and. any(transfer(x_ref, 0_int64, n) /= transfer(x_own, 0_int64, n)))) then
        differ = differ + 1
        if (first_bad == 0) first_bad = i
      end if
    end do
    write (detail, '(a,i0,a,i0,a,i0,a,i0)') "n = ", n, ": ", differ, " systems differ from dgesv (first: system ", &
      first_bad, "); zero pivots ", zero_pivots
    call check_true(t, "lapack: solve_dense's LU = dgesv bit for bit", differ == 0, trim(detail))
    call check_true(t, "lapack: the bitwise set has zero pivots", zero_pivots > 0, trim(detail))
  end subroutine bitwise

  !> system_count systems of size n: the verdicts must agree; both kinds must occur.
  subroutine fuzz(t, n)
    type(test_counts_t), intent(inout) :: t
    integer, intent(in) :: n
    real(wp) :: a(n, n), x(n), b(n)
    type(error_t), allocatable :: error
    integer(int64) :: state
    integer :: i, differ, singular, regular
    character(len=160) :: detail
    state = 1400_int64 + n
    differ = 0
    singular = 0
    regular = 0
    do i = 1, system_count
      call random_system(state, mod(i, 4), a)
      b = 1.0_wp
      call solve_dense(a, b, x, error)
      if (allocated(error) .neqv. singular_by_estimate(a)) differ = differ + 1
      if (allocated(error)) then
        singular = singular + 1
      else
        regular = regular + 1
      end if
    end do
    write (detail, '(a,i0,a,i0,a,i0,a,i0)') "n = ", n, ": ", differ, " verdicts differ; singular ", singular, &
      ", regular ", regular
    call check_true(t, "lapack: cheap singular test = dgecon's verdict", differ == 0, trim(detail))
    call check_true(t, "lapack: the fuzzed set has singular and regular systems", singular > system_count / 10 &
                    .and. regular > system_count / 10, trim(detail))
  end subroutine fuzz

  !> What the cheap screen rests on: dgecon's rcond >= 1/(||A||_1 * bound) for every
  !> fuzzed system of every family with a finite bound (dgecon's estimate of ||(LU)^-1||_1
  !> is a lower bound of it, the bound an upper one; halving the bound fails ~700 of the
  !> 3x3 systems, where it is often tight).
  subroutine bound_holds(t, n)
    type(test_counts_t), intent(inout) :: t
    integer, intent(in) :: n
    real(wp) :: a(n, n), b(n), x(n), lu(n, n), rc, bound, anorm, ratio, worst
    type(error_t), allocatable :: error
    integer(int64) :: state
    integer :: i, ipiv(n), info, bad, tested
    logical :: finite
    character(len=200) :: detail
    state = 3400_int64 + n
    bad = 0
    tested = 0
    worst = huge(1.0_wp)
    b = 1.0_wp
    do i = 1, system_count
      call random_system(state, mod(i, 8), a)
      call solve_by(by_port, a, b, lu, ipiv, x, info)
      if (info > 0) cycle
      call inverse_norm_bound(lu, bound, finite)
      if (.not. finite) cycle
      call solve_dense(a, b, x, error, rc)
      if (.not. rc > 0.0_wp) cycle
      anorm = maxval(sum(abs(a), dim=1))
      ! rc * anorm * bound >= 1 (up to roundoff)
      ratio = rc * anorm * bound
      tested = tested + 1
      worst = min(worst, ratio)
      if (.not. ratio >= 1.0_wp - 1.0e-9_wp) bad = bad + 1
    end do
    write (detail, '(a,i0,a,i0,a,i0,a,es10.3)') "n = ", n, ": ", bad, " of ", tested, &
      " systems with rcond * ||A|| * bound < 1; smallest ", worst
    call check_true(t, "lapack: the screen's bound is an upper bound of ||(LU)^-1||", bad == 0, trim(detail))
    call check_true(t, "lapack: the bound was tested on most systems", tested > system_count / 2, trim(detail))
  end subroutine bound_holds

  !> A random system of a family: 0 random, 1 badly scaled rows and columns, 2 and 3 a rank
  !> deficient matrix plus a perturbation of relative size 1e-18 .. 1e-6, 4 and 5 sparse with
  !> signed zeros, 6 small integers, 7 a subnormal column.
  subroutine random_system(state, family, a)
    integer(int64), intent(inout) :: state
    integer, intent(in) :: family
    real(wp), intent(out) :: a(:, :)
    real(wp) :: c(size(a, 1)), eps
    integer :: i, j, n
    n = size(a, 1)
    do j = 1, n
      do i = 1, n
        a(i, j) = 2.0_wp * uniform(state) - 1.0_wp
      end do
    end do
    select case (family)
    case (1)
      do i = 1, n
        a(i, :) = a(i, :) * 10.0_wp**(6.0_wp * uniform(state) - 3.0_wp)
        a(:, i) = a(:, i) * 10.0_wp**(6.0_wp * uniform(state) - 3.0_wp)
      end do
    case (2, 3)
      do j = 1, n - 1
        c(j) = 2.0_wp * uniform(state) - 1.0_wp
      end do
      a(:, n) = matmul(a(:, 1:n - 1), c(1:n - 1))
      eps = 10.0_wp**(-18.0_wp + 12.0_wp * uniform(state))
      do i = 1, n
        a(i, n) = a(i, n) + eps * (2.0_wp * uniform(state) - 1.0_wp)
      end do
    case (4, 5)
      ! sparse, with signed zeros (the dyads' matrices have structural zeros)
      do j = 1, n
        do i = 1, n
          eps = uniform(state)
          if (eps < 0.25_wp) then
            a(i, j) = 0.0_wp
          else if (eps < 0.5_wp) then
            a(i, j) = -0.0_wp
          end if
        end do
      end do
    case (6)
      ! small integers: pivot ties, exact cancellations, exact zero pivots
      a = real(nint(4.0_wp * a), wp)
    case (7)
      ! a subnormal column (pivots below the smallest normal number)
      a(:, 1 + mod(int(uniform(state) * n), n)) = a(:, 1) * 1.0e-310_wp
    case default ! a plain random matrix
    end select
  end subroutine random_system

  !> A uniform deviate in [0, 1) (xorshift64: shifts and exclusive ors only, no signed
  !> overflow, the same sequence in every build).
  real(wp) function uniform(state)
    integer(int64), intent(inout) :: state
    state = ieor(state, shiftl(state, 13))
    state = ieor(state, shiftr(state, 7))
    state = ieor(state, shiftl(state, 17))
    uniform = real(shiftr(state, 11), wp) * 2.0_wp**(-53)
  end function uniform

end module test_lapack
