!> The one wrapper around LAPACK: dense solve with a condition estimate, `info` turned into `error_t`.
!>
!> The factorisation and the solve are LAPACK's dgesv done here, operation for operation:
!> dgetrf2's recursive partial-pivoting LU (idamax's pivot choice, dscal by the pivot's
!> reciprocal, the updates of dtrsm and dgemm as the reference BLAS write them, down to which
!> updates dtrsm skips for a zero), unrolled into one loop over the columns, and dgetrs'
!> substitutions. The factors, the pivots, the
!> zero-pivot verdict and the solution are bit for bit those of the system library's dgesv
!> (the test `lapack` compares them on fuzzed systems), without its call and argument-checking
!> overhead, which cost more than the arithmetic for the 6x6 and 3x3 systems solved here.
!>
!> The singular-position test is dgecon's estimate against rcond_threshold, as it always was;
!> dgecon is called only when a cheap bound cannot settle it. dgecon's rcond is 1/(anorm*est)
!> with est <= ||(LU)^-1||_1 (a lower-bound estimator), and ||(LU)^-1||_1 <=
!> ||U^-1||_1 * ||L^-1||_1, bounded in turn through the triangles' comparison matrices in ~n^2
!> flops (inverse_norm_bound). When
!> 1/(anorm * that bound) is at least screen_factor * rcond_threshold, dgecon's rcond is above
!> the threshold too (by a margin far beyond the roundoff of either computation), so the
!> answer is the same without calling it; otherwise dgecon decides exactly as before.
module kinetostat_lapack
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  implicit none
  private
  public :: solve_dense, factor_dense, solve_factored, trsm_table, lu_solve_transposed
  public :: rcond_threshold, singular_by_estimate, solve_by, by_dgesv, by_port, inverse_norm_bound

  !> Margin of the cheap test: dgecon is skipped only when the bound puts rcond at least this
  !> many times above the threshold.
  real(wp), parameter :: screen_factor = 10.0_wp

  !> Reciprocal condition number below which a system counts as singular (dead position).
  real(wp), parameter :: rcond_threshold = 1.0e-12_wp

  !> Orders up to this are factored in fixed local arrays (the generic engine's 6 x 6 and
  !> 3 x 3, the cam's 3 x 3); larger ones allocate their workspace.
  integer, parameter :: small_order = 8

  !> solve_by: LAPACK's dgesv.
  integer, parameter :: by_dgesv = 1
  !> solve_by: the port (lu_factor, lu_solve: what solve_dense computes).
  integer, parameter :: by_port = 2

  ! LAPACK's Fortran 77 interfaces take assumed-size arrays.
  ! allow(assumed-size)
  interface
    !> LU factorisation and solve of a general system (LAPACK).
    pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      implicit none
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*)
      integer, intent(out) :: info
    end subroutine dgesv
    !> Reciprocal condition number estimate from an LU factorisation (LAPACK).
    pure subroutine dgecon(norm, n, a, lda, anorm, rcond, work, iwork, info)
      import :: wp
      implicit none
      character, intent(in) :: norm
      integer, intent(in) :: n, lda
      real(wp), intent(in) :: a(lda, *), anorm
      real(wp), intent(out) :: rcond
      real(wp), intent(inout) :: work(*)
      integer, intent(inout) :: iwork(*)
      integer, intent(out) :: info
    end subroutine dgecon
  end interface

contains

  !> Solve a*x = b for a small dense square system; singular or ill-conditioned -> geometry error.
  pure subroutine solve_dense(a, b, x, error, rcond)
    !> Coefficient matrix (n x n), unchanged.
    real(wp), intent(in) :: a(:, :)
    !> Right-hand side (n).
    real(wp), intent(in) :: b(:)
    !> Solution (n).
    real(wp), intent(out) :: x(:)
    !> Set when the matrix is singular or its reciprocal condition is below `rcond_threshold`.
    type(error_t), allocatable, intent(out) :: error
    !> Reciprocal condition number estimate (1-norm, dgecon's), if wanted (then always computed).
    real(wp), intent(out), optional :: rcond
    ! the workspace of the orders solved per step lives in fixed arrays (no heap per call)
    real(wp), target :: lu_small(small_order, small_order)
    integer, target :: ipiv_small(small_order)
    real(wp), allocatable, target :: lu_big(:, :)
    integer, allocatable, target :: ipiv_big(:)
    real(wp), pointer :: lu(:, :)
    integer, pointer :: ipiv(:)
    integer :: n
    n = size(a, 1)
    if (n <= small_order) then
      lu => lu_small(1:n, 1:n)
      ipiv => ipiv_small(1:n)
    else
      allocate (lu_big(n, n), ipiv_big(n))
      lu => lu_big
      ipiv => ipiv_big
    end if
    call solve_in(a, b, x, lu, ipiv, error, rcond)
  end subroutine solve_dense

  !> solve_dense with its workspace: the factors `lu` (n x n) and pivots `ipiv`.
  pure subroutine solve_in(a, b, x, lu, ipiv, error, rcond)
    real(wp), intent(in) :: a(:, :)
    real(wp), intent(in) :: b(:)
    real(wp), intent(out) :: x(:)
    real(wp), intent(out) :: lu(:, :)
    integer, intent(out) :: ipiv(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: rcond
    x = 0.0_wp
    call factor_in(a, lu, ipiv, error, rcond)
    if (allocated(error)) return
    x = b
    call lu_solve(lu, ipiv, x)
  end subroutine solve_in

  !> solve_dense's factorisation alone, for several right-hand sides of one matrix: the
  !> factors `lu` and pivots `ipiv` of `a` (caller's workspace, n x n and n), with the same
  !> singular-position verdict; then solve_factored for each right-hand side gives bit for bit
  !> what solve_dense gives.
  pure subroutine factor_dense(a, lu, ipiv, error, trsm)
    !> Coefficient matrix (n x n), unchanged.
    real(wp), intent(in) :: a(:, :)
    !> Its LU factors (n x n).
    real(wp), intent(out) :: lu(:, :)
    !> Row interchanges (n).
    integer, intent(out) :: ipiv(:)
    !> Set when the matrix is singular or its reciprocal condition is below `rcond_threshold`.
    type(error_t), allocatable, intent(out) :: error
    !> trsm_table(n), for a caller that factors many matrices of order n (the same factors,
    !> without working out dtrsm's rows at every zero).
    integer, intent(in), optional :: trsm(:, :)
    call factor_in(a, lu, ipiv, error, trsm=trsm)
  end subroutine factor_dense

  !> trsm_last(n, j, k) of every pair of columns j < k of an n x n factorisation (entry (j, k);
  !> the rest 0): factor_dense's optional table.
  pure function trsm_table(n) result(table)
    !> Order of the matrices.
    integer, intent(in) :: n
    integer :: table(n, n)
    integer :: j, k
    table = 0
    do k = 2, n
      do j = 1, k - 1
        table(j, k) = trsm_last(n, j, k)
      end do
    end do
  end function trsm_table

  !> Solves with factor_dense's factors: `x` (the right-hand side) becomes the solution.
  pure subroutine solve_factored(lu, ipiv, x)
    !> Factors from factor_dense.
    real(wp), intent(in) :: lu(:, :)
    !> Row interchanges from factor_dense.
    integer, intent(in) :: ipiv(:)
    !> Right-hand side in, solution out.
    real(wp), intent(inout) :: x(:)
    call lu_solve(lu, ipiv, x)
  end subroutine solve_factored

  !> The factorisation and the singular-position test of solve_in.
  pure subroutine factor_in(a, lu, ipiv, error, rcond, trsm)
    real(wp), intent(in) :: a(:, :)
    real(wp), intent(out) :: lu(:, :)
    integer, intent(out) :: ipiv(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp), intent(out), optional :: rcond
    integer, intent(in), optional :: trsm(:, :)
    real(wp) :: anorm, rc, bound
    integer :: info
    logical :: settled, finite

    if (present(rcond)) rcond = 0.0_wp
    lu = a
    anorm = maxval(sum(abs(a), dim=1))
    call lu_factor(lu, ipiv, info, trsm)
    if (info > 0) then
      call fatal_error(error, exit_geometry, "singular system (zero pivot)")
      return
    end if
    settled = .false.
    if (.not. present(rcond)) then
      call inverse_norm_bound(lu, bound, finite)
      if (finite) settled = 1.0_wp / (anorm * bound) >= screen_factor * rcond_threshold
    end if
    if (.not. settled) then
      call estimate_rcond(lu, anorm, rc, info)
      if (present(rcond)) rcond = rc
      if (info /= 0 .or. .not. (rc >= rcond_threshold)) then
        call fatal_error(error, exit_geometry, "ill-conditioned system (dead or singular position)")
        return
      end if
    end if
  end subroutine factor_in

  !> dgetrf2's LU factorisation with partial pivoting of the square `a`: L (unit diagonal)
  !> below and U on and above the diagonal; `info` > 0: U(info, info) is exactly zero. The
  !> reference LAPACK 3.11 arithmetic, done column by column (left-looking): dgetrf2's
  !> recursion applies to every entry the same updates in the same order (k = 1, 2, ...), each
  !> a(i,j) - u(k,j)*l(i,k) rounded once (dgemm's a + (-u)*l is the same number), its row swaps
  !> only move data, and its pivots are idamax's; what the recursion changes is which updates
  !> dtrsm makes, and dtrsm skips an update whose u(k,j) is zero (which can turn -0 into +0)
  !> while dgemm does not: trsm_last gives the rows of dtrsm's updates, counted after the
  !> pivots of its node's left part (all pivots before column j are, here).
  pure subroutine lu_factor(a, ipiv, info, trsm)
    !> Matrix, overwritten by its factors.
    real(wp), intent(inout) :: a(:, :)
    !> Row interchanges: row k was swapped with row ipiv(k).
    integer, intent(out) :: ipiv(:)
    !> 0, or the first zero pivot.
    integer, intent(out) :: info
    !> trsm_table(n), if the caller keeps it.
    integer, intent(in), optional :: trsm(:, :)
    real(wp) :: temp, amax, u
    integer :: n, i, j, k, p, last
    n = size(a, 1)
    info = 0
    do k = 1, n
      ! column k: the updates from columns 1 .. k-1, in that order, rows in their places
      ! after the pivots so far (where dtrsm's rows are: it works after its node's pivots)
      do j = 1, k - 1
        u = a(j, k)
        last = j
        if (u == 0.0_wp) then
          if (present(trsm)) then
            last = trsm(j, k)
          else
            last = trsm_last(n, j, k)
          end if
        end if
        do i = last + 1, n
          a(i, k) = a(i, k) - u * a(i, j)
        end do
      end do
      ! idamax: the first entry of largest magnitude
      p = k
      amax = abs(a(k, k))
      do i = k + 1, n
        if (abs(a(i, k)) > amax) then
          p = i
          amax = abs(a(i, k))
        end if
      end do
      ipiv(k) = p
      if (a(p, k) /= 0.0_wp) then
        if (p /= k) then
          do j = 1, n
            temp = a(k, j)
            a(k, j) = a(p, j)
            a(p, j) = temp
          end do
        end if
        if (abs(a(k, k)) >= tiny(1.0_wp)) then
          temp = 1.0_wp / a(k, k)
          do i = k + 1, n
            a(i, k) = temp * a(i, k)
          end do
        else
          do i = k + 1, n
            a(i, k) = a(i, k) / a(k, k)
          end do
        end if
      else if (info == 0) then
        info = k
      end if
    end do
  end subroutine lu_factor

  !> The last row updated by dtrsm (not dgemm) with column k in column j (k < j) when dgetrf2
  !> factors an n x n matrix (k when none): at the node of its recursion that puts k in its
  !> left part (columns c0 .. c0+n1-1, n1 = half its width) and j in its right part, dtrsm
  !> updates rows k+1 .. c0+n1-1.
  pure integer function trsm_last(n, k, j) result(last)
    !> Order of the matrix.
    integer, intent(in) :: n
    !> Pivot column and updated column.
    integer, intent(in) :: k, j
    integer :: c0, width, n1
    c0 = 1
    width = n
    last = k
    do while (width > 1)
      n1 = min(n - c0 + 1, width) / 2
      if (k < c0 + n1 .and. j >= c0 + n1) then
        last = max(k, c0 + n1 - 1)
        return
      else if (j < c0 + n1) then
        width = n1
      else
        c0 = c0 + n1
        width = width - n1
      end if
    end do
  end function trsm_last

  !> dgetrs for one right-hand side: `x` = (P L U)^-1 `x` from lu_factor's factors (dlaswp,
  !> then dtrsm's forward and back substitutions, which skip a zero as the reference does).
  pure subroutine lu_solve(lu, ipiv, x)
    !> Factors.
    real(wp), intent(in) :: lu(:, :)
    !> Row interchanges.
    integer, intent(in) :: ipiv(:)
    !> Right-hand side in, solution out.
    real(wp), intent(inout) :: x(:)
    integer :: n, i, k
    n = size(lu, 1)
    do k = 1, n
      call interchange(x, k, ipiv(k))
    end do
    do k = 1, n
      if (x(k) /= 0.0_wp) then
        do i = k + 1, n
          x(i) = x(i) - x(k) * lu(i, k)
        end do
      end if
    end do
    do k = n, 1, -1
      if (x(k) /= 0.0_wp) then
        x(k) = x(k) / lu(k, k)
        do i = 1, k - 1
          x(i) = x(i) - x(k) * lu(i, k)
        end do
      end if
    end do
  end subroutine lu_solve

  !> x = A^-T x from A's factors P L U (factor_dense): U^T and L^T by
  !> substitution, then the row interchanges in reverse (dgetrs with trans = 'T').
  pure subroutine lu_solve_transposed(lu, ipiv, x)
    real(wp), intent(in) :: lu(:, :)
    integer, intent(in) :: ipiv(:)
    real(wp), intent(inout) :: x(:)
    real(wp) :: s
    integer :: n, i, k
    n = size(lu, 1)
    do k = 1, n
      s = x(k)
      do i = 1, k - 1
        s = s - lu(i, k) * x(i)
      end do
      x(k) = s / lu(k, k)
    end do
    do k = n, 1, -1
      s = x(k)
      do i = k + 1, n
        s = s - lu(i, k) * x(i)
      end do
      x(k) = s
    end do
    do k = n, 1, -1
      call interchange(x, k, ipiv(k))
    end do
  end subroutine lu_solve_transposed

  !> Elements k and j of x swapped (nothing when k = j): one row interchange of dlaswp.
  pure subroutine interchange(x, k, j)
    real(wp), intent(inout) :: x(:)
    integer, intent(in) :: k, j
    real(wp) :: temp
    if (j == k) return
    temp = x(k)
    x(k) = x(j)
    x(j) = temp
  end subroutine interchange

  !> One system solved by LAPACK's dgesv itself (`by_dgesv`, the reference of the tests) or
  !> as solve_dense computes it (`by_port`; the tests compare the two bit for bit): factors
  !> `lu`, pivots `ipiv`, solution `x` (set only when `info` = 0) and `info` (dgesv's: 0, or
  !> the first zero pivot).
  pure subroutine solve_by(solver, a, b, lu, ipiv, x, info)
    !> by_dgesv or by_port.
    integer, intent(in) :: solver
    !> Coefficient matrix (n x n).
    real(wp), intent(in) :: a(:, :)
    !> Right-hand side (n).
    real(wp), intent(in) :: b(:)
    !> The factors (dgetrf's or lu_factor's).
    real(wp), intent(out) :: lu(:, :)
    !> The row interchanges.
    integer, intent(out) :: ipiv(:)
    !> Solution.
    real(wp), intent(out) :: x(:)
    !> 0, or the first zero pivot.
    integer, intent(out) :: info
    real(wp) :: rhs(size(a, 1), 1)
    integer :: n
    lu = a
    if (solver == by_dgesv) then
      n = size(a, 1)
      rhs(:, 1) = b
      call dgesv(n, 1, lu, n, ipiv, rhs, n, info)
      x = rhs(:, 1)
    else
      call lu_factor(lu, ipiv, info)
      x = b
      if (info == 0) call lu_solve(lu, ipiv, x)
    end if
  end subroutine solve_by

  !> dgecon's reciprocal condition estimate (1-norm) from the LU factors (`lu` may be a
  !> section of a larger array: dgecon gets a contiguous copy).
  pure subroutine estimate_rcond(lu, anorm, rc, info)
    real(wp), intent(in) :: lu(:, :)
    real(wp), intent(in) :: anorm
    real(wp), intent(out) :: rc
    integer, intent(out) :: info
    real(wp) :: work(4 * size(lu, 1)), factors(size(lu, 1), size(lu, 1))
    integer :: iwork(size(lu, 1)), n
    n = size(lu, 1)
    factors = lu
    call dgecon('1', n, factors, n, anorm, rc, work, iwork, info)
  end subroutine estimate_rcond

  !> An upper bound of ||(L U)^-1||_1 from dgetrf's factors in `lu` (unit lower L below the
  !> diagonal, U on and above it): ||U^-1||_1 * ||L^-1||_1, each bounded through its
  !> comparison matrix M(T) (|diagonal|, -|off-diagonal|): |T^-1| <= M(T)^-1 entrywise for a
  !> triangular T. M(U) = (I - N) D with D = |diag U| and N >= 0 strictly upper, whose
  !> column j is U's off-diagonal column j in magnitude over |u_jj|, of 1-norm c_j; a unit
  !> triangular I - N is the product of the elementary I - n_j e_j^T (cross terms vanish in
  !> the right order), whose inverses I + n_j e_j^T have 1-norm 1 + c_j. Hence
  !> ||U^-1||_1 <= prod(1 + c_j) / min|u_jj|, and ||L^-1||_1 <= prod(1 + l_j) with l_j the
  !> 1-norm of L's column j below the diagonal: column sums and n independent divisions
  !> (no chain of dependent divisions as in solving with M(U)). Looser than that solve; a
  !> loose bound only leaves more systems to dgecon.
  pure subroutine inverse_norm_bound(lu, bound, finite)
    !> The factors.
    real(wp), intent(in) :: lu(:, :)
    !> The bound.
    real(wp), intent(out) :: bound
    !> False when the bound is not a finite positive number (it then settles nothing).
    logical, intent(out) :: finite
    real(wp) :: col_u, col_l, d_min, prod_u, prod_l
    integer :: n, i, j
    n = size(lu, 1)
    prod_u = 1.0_wp
    prod_l = 1.0_wp
    d_min = huge(1.0_wp)
    do j = 1, n
      col_u = 0.0_wp
      do i = 1, j - 1
        col_u = col_u + abs(lu(i, j))
      end do
      col_l = 0.0_wp
      do i = j + 1, n
        col_l = col_l + abs(lu(i, j))
      end do
      prod_u = prod_u * (1.0_wp + col_u / abs(lu(j, j)))
      prod_l = prod_l * (1.0_wp + col_l)
      d_min = min(d_min, abs(lu(j, j)))
    end do
    bound = prod_u * prod_l / d_min
    ! (NaN or infinity anywhere: no bound)
    finite = bound <= huge(1.0_wp) .and. d_min > 0.0_wp
  end subroutine inverse_norm_bound

  !> The singular-position test as it was before the cheap bound: dgesv's zero pivot, or
  !> dgecon's estimate below rcond_threshold (the reference of the tests).
  pure logical function singular_by_estimate(a)
    !> Coefficient matrix (n x n).
    real(wp), intent(in) :: a(:, :)
    real(wp) :: lu(size(a, 1), size(a, 1)), rhs(size(a, 1), 1), rc
    integer :: ipiv(size(a, 1)), info, n
    n = size(a, 1)
    lu = a
    rhs = 1.0_wp
    call dgesv(n, 1, lu, n, ipiv, rhs, n, info)
    singular_by_estimate = info /= 0
    if (singular_by_estimate) return
    call estimate_rcond(lu, maxval(sum(abs(a), dim=1)), rc, info)
    singular_by_estimate = info /= 0 .or. .not. (rc >= rcond_threshold)
  end function singular_by_estimate

end module kinetostat_lapack
