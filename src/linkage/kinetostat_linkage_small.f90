!> Small systems of the general engine's units solved by closed forms instead of an LU
!> factorisation: a 3 x 3 system (an input unit of one link) by Cramer's rule, and the 6 x 6
!> system of a dyad's two bodies by reduction to a 2 x 2. A dyad's system (the group method's
!> free bodies, and J's diagonal block transposed: the Lagrange multipliers) has three
!> equations per link (rows 1-3 of the first, 4-6 of the second) and two unknowns per pair:
!> an outer pair acts on the first link only (its columns are 0 in rows 4-6), another on the
!> second only, the inner pair on both. The cross product a of an outer pair's two 3-columns
!> is orthogonal to both, so a . (that link's equations) leaves the inner pair's unknowns
!> alone (for a turning pair: the moments about its joint; for a sliding pair: the forces
!> along its guide): two equations in the inner pair's two unknowns; each outer pair's
!> unknowns then follow from the two of its link's equations with the largest minor (a
!> component of a). The transposed problem (J's block itself: the velocities and
!> accelerations) is the same reduction with the roles of rows and columns exchanged: each
!> outer pair's two rows fix its link's three coordinates up to their null vector (the cross
!> product of the rows), the inner pair's two rows give the two multiples. Each solve
!> reports whether its determinants are clear of zero (above `screen` of their entries'
!> scale); where one is not, the caller solves densely (LU), which also decides whether the
!> position is singular.
module kinetostat_linkage_small
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: solve3, two_body_solve, small_screen
  public :: small_factors_t, factor3, solve3_factored, dyad_factor, dyad_solve, dyad_solve_transposed

  !> A determinant below this fraction of its entries' scale is left to the dense solve.
  real(wp), parameter :: small_screen = 1.0e-6_wp

  !> A unit's block of J prepared for its closed-form solves (factor3, dyad_factor): for an
  !> input unit of one link (3 x 3 block B) the rows of B^-1 as columns (c); for a dyad
  !> (6 x 6 block: two constraint rows of each pair, the two links' coordinates) each outer
  !> pair's null vector of its rows (n), the largest component's index (pick) and the inner
  !> pair's 2 x 2 system (p: its rows applied to the null vectors) with its determinant.
  type :: small_factors_t
    real(wp) :: c(3, 3) = 0.0_wp
    real(wp) :: n(3, 2) = 0.0_wp
    integer :: pick(2) = 1
    real(wp) :: p(2, 2) = 0.0_wp, det = 0.0_wp
  end type small_factors_t

contains

  !> Cross product of two 3-vectors.
  pure function cross3(u, v) result(w)
    real(wp), intent(in) :: u(3), v(3)
    real(wp) :: w(3)
    w(1) = u(2) * v(3) - u(3) * v(2)
    w(2) = u(3) * v(1) - u(1) * v(3)
    w(3) = u(1) * v(2) - u(2) * v(1)
  end function cross3

  !> x = a^-1 b for a 3 x 3 `a` by Cramer's rule; `ok` false (x unset) when det(a) is below
  !> small_screen of the product of its columns' lengths.
  pure subroutine solve3(a, b, x, ok)
    !> The matrix.
    real(wp), intent(in) :: a(:, :)
    !> Right-hand side (3).
    real(wp), intent(in) :: b(:)
    !> Solution (3).
    real(wp), intent(out) :: x(:)
    logical, intent(out) :: ok
    real(wp) :: c23(3), c31(3), c12(3), det, scale
    c23 = cross3(a(1:3, 2), a(1:3, 3))
    c31 = cross3(a(1:3, 3), a(1:3, 1))
    c12 = cross3(a(1:3, 1), a(1:3, 2))
    det = dot_product(a(1:3, 1), c23)
    scale = norm3(a(1:3, 1)) * norm3(a(1:3, 2)) * norm3(a(1:3, 3))
    ok = abs(det) > small_screen * scale
    if (.not. ok) return
    x(1) = dot_product(b(1:3), c23) / det
    x(2) = dot_product(b(1:3), c31) / det
    x(3) = dot_product(b(1:3), c12) / det
  end subroutine solve3

  !> A dyad's system a x = b (6 x 6; rows 1-3: the first link's equations, 4-6: the
  !> second's) whose columns c1, c1+1 (an outer pair) are 0 in rows 4-6, columns c2, c2+1
  !> (the other outer pair) 0 in rows 1-3, columns cm, cm+1 the inner pair's: by the module's
  !> reduction. `ok` false (x unset) when a determinant is not clear of zero.
  pure subroutine two_body_solve(a, b, c1, cm, c2, x, ok)
    !> The system's matrix (6 x 6) and right-hand side (6).
    real(wp), intent(in) :: a(:, :), b(:)
    !> First columns of the first link's outer pair, the inner pair, the second's outer pair.
    integer, intent(in) :: c1, cm, c2
    !> Solution (6).
    real(wp), intent(out) :: x(:)
    logical, intent(out) :: ok
    real(wp) :: n1(3), n2(3), m11, m12, m21, m22, r1, r2, det, res(3)
    n1 = cross3(a(1:3, c1), a(1:3, c1 + 1))
    n2 = cross3(a(4:6, c2), a(4:6, c2 + 1))
    m11 = dot_product(n1, a(1:3, cm))
    m12 = dot_product(n1, a(1:3, cm + 1))
    m21 = dot_product(n2, a(4:6, cm))
    m22 = dot_product(n2, a(4:6, cm + 1))
    r1 = dot_product(n1, b(1:3))
    r2 = dot_product(n2, b(4:6))
    det = m11 * m22 - m12 * m21
    ok = abs(det) > small_screen * (abs(m11) + abs(m12)) * (abs(m21) + abs(m22))
    if (.not. ok) return
    x(cm:cm + 1) = cramer2(m11, m12, m21, m22, r1, r2, det)
    res = b(1:3) - a(1:3, cm) * x(cm) - a(1:3, cm + 1) * x(cm + 1)
    call solve_3x2(a(1:3, c1), a(1:3, c1 + 1), n1, res, x(c1), x(c1 + 1), ok)
    if (.not. ok) return
    res = b(4:6) - a(4:6, cm) * x(cm) - a(4:6, cm + 1) * x(cm + 1)
    call solve_3x2(a(4:6, c2), a(4:6, c2 + 1), n2, res, x(c2), x(c2 + 1), ok)
  end subroutine two_body_solve

  !> y1 u + y2 v = r for a consistent r (3 equations, 2 unknowns): the two equations whose
  !> minor (a component of n = u x v) is the largest.
  pure subroutine solve_3x2(u, v, n, r, y1, y2, ok)
    real(wp), intent(in) :: u(3), v(3), n(3), r(3)
    real(wp), intent(out) :: y1, y2
    logical, intent(out) :: ok
    integer :: i, j, k
    real(wp) :: y(2)
    i = maxloc(abs(n), 1)
    call others(i, j, k)
    ok = abs(n(i)) > small_screen * norm3(u) * norm3(v)
    if (.not. ok) return
    ! rows j, k: [u(j) v(j); u(k) v(k)], whose determinant is n(i)
    y = cramer2(u(j), v(j), u(k), v(k), r(j), r(k), n(i))
    y1 = y(1)
    y2 = y(2)
  end subroutine solve_3x2

  !> x of [m11 m12; m21 m22] x = [r1; r2] by Cramer's rule, det = m11 m22 - m12 m21 given
  !> (clear of zero: the caller screens it).
  pure function cramer2(m11, m12, m21, m22, r1, r2, det) result(x)
    real(wp), intent(in) :: m11, m12, m21, m22, r1, r2, det
    real(wp) :: x(2)
    x(1) = (r1 * m22 - m12 * r2) / det
    x(2) = (m11 * r2 - m21 * r1) / det
  end function cramer2

  !> The two indices of 1..3 after i in cyclic order (i, j, k: an even permutation).
  pure subroutine others(i, j, k)
    integer, intent(in) :: i
    integer, intent(out) :: j, k
    j = mod(i, 3) + 1
    k = mod(j, 3) + 1
  end subroutine others

  !> Length of a 3-vector.
  pure real(wp) function norm3(u)
    real(wp), intent(in) :: u(3)
    norm3 = sqrt(u(1)**2 + u(2)**2 + u(3)**2)
  end function norm3

  !> A 3 x 3 block `b` for solve3_factored; `ok` false when det(b) is not clear of zero.
  pure subroutine factor3(b, f, ok)
    real(wp), intent(in) :: b(:, :)
    type(small_factors_t), intent(inout) :: f
    logical, intent(out) :: ok
    real(wp) :: det
    f%c(:, 1) = cross3(b(1:3, 2), b(1:3, 3))
    f%c(:, 2) = cross3(b(1:3, 3), b(1:3, 1))
    f%c(:, 3) = cross3(b(1:3, 1), b(1:3, 2))
    det = dot_product(b(1:3, 1), f%c(:, 1))
    ok = abs(det) > small_screen * norm3(b(1:3, 1)) * norm3(b(1:3, 2)) * norm3(b(1:3, 3))
    if (.not. ok) return
    f%c = f%c / det
  end subroutine factor3

  !> x = B^-1 x (or B^-T x, `transposed`) with factor3's factors.
  pure subroutine solve3_factored(f, x, transposed)
    type(small_factors_t), intent(in) :: f
    real(wp), intent(inout) :: x(:)
    logical, intent(in) :: transposed
    real(wp) :: r(3)
    r = x(1:3)
    if (transposed) then
      x(1:3) = f%c(:, 1) * r(1) + f%c(:, 2) * r(2) + f%c(:, 3) * r(3)
    else
      x(1) = dot_product(f%c(:, 1), r)
      x(2) = dot_product(f%c(:, 2), r)
      x(3) = dot_product(f%c(:, 3), r)
    end if
  end subroutine solve3_factored

  !> A dyad's block `b` of J (rows: the pairs' constraint rows, c1 and c1+1 the outer pair of
  !> the first link, cm and cm+1 the inner pair, c2 and c2+1 the outer pair of the second;
  !> columns 1-3 the first link's coordinates, 4-6 the second's) for dyad_solve and
  !> dyad_solve_transposed; `ok` false when a determinant is not clear of zero.
  pure subroutine dyad_factor(b, c1, cm, c2, f, ok)
    real(wp), intent(in) :: b(:, :)
    integer, intent(in) :: c1, cm, c2
    type(small_factors_t), intent(inout) :: f
    logical, intent(out) :: ok
    real(wp) :: u1(3), v1(3), u2(3), v2(3)
    integer :: i
    ! (the outer pairs' rows copied: a row of b is no contiguous array)
    u1 = [b(c1, 1), b(c1, 2), b(c1, 3)]
    v1 = [b(c1 + 1, 1), b(c1 + 1, 2), b(c1 + 1, 3)]
    u2 = [b(c2, 4), b(c2, 5), b(c2, 6)]
    v2 = [b(c2 + 1, 4), b(c2 + 1, 5), b(c2 + 1, 6)]
    f%n(:, 1) = cross3(u1, v1)
    f%n(:, 2) = cross3(u2, v2)
    f%pick(1) = maxloc(abs(f%n(:, 1)), 1)
    f%pick(2) = maxloc(abs(f%n(:, 2)), 1)
    ok = abs(f%n(f%pick(1), 1)) > small_screen * norm3(u1) * norm3(v1) .and. &
         abs(f%n(f%pick(2), 2)) > small_screen * norm3(u2) * norm3(v2)
    if (.not. ok) return
    do i = 1, 2
      f%p(i, 1) = dot_product(b(cm + i - 1, 1:3), f%n(:, 1))
      f%p(i, 2) = dot_product(b(cm + i - 1, 4:6), f%n(:, 2))
    end do
    f%det = f%p(1, 1) * f%p(2, 2) - f%p(1, 2) * f%p(2, 1)
    ok = abs(f%det) > small_screen * (abs(f%p(1, 1)) + abs(f%p(2, 1))) * (abs(f%p(1, 2)) + abs(f%p(2, 2)))
  end subroutine dyad_factor

  !> x = B^-1 x with dyad_factor's factors (x: the block's rows in, its columns out): each
  !> outer pair's rows fix its link's coordinates up to a multiple of its null vector, the
  !> inner pair's rows the two multiples.
  pure subroutine dyad_solve(b, c1, cm, c2, f, x)
    real(wp), intent(in) :: b(:, :)
    integer, intent(in) :: c1, cm, c2
    type(small_factors_t), intent(in) :: f
    real(wp), intent(inout) :: x(:)
    real(wp) :: r(6), x1(3), x2(3), rm(2), t(2)
    r = x(1:6)
    call particular(b, c1, 0, f%n(:, 1), f%pick(1), r(c1:c1 + 1), x1)
    call particular(b, c2, 3, f%n(:, 2), f%pick(2), r(c2:c2 + 1), x2)
    rm(1) = r(cm) - dot_product(b(cm, 1:3), x1) - dot_product(b(cm, 4:6), x2)
    rm(2) = r(cm + 1) - dot_product(b(cm + 1, 1:3), x1) - dot_product(b(cm + 1, 4:6), x2)
    t = cramer2(f%p(1, 1), f%p(1, 2), f%p(2, 1), f%p(2, 2), rm(1), rm(2), f%det)
    x(1:3) = x1 + t(1) * f%n(:, 1)
    x(4:6) = x2 + t(2) * f%n(:, 2)
  end subroutine dyad_solve

  !> y = B^-T y with dyad_factor's factors (y: the block's columns in, its rows out): each
  !> null vector times its link's equations gives the inner pair's two unknowns, each link's
  !> equations then its outer pair's two.
  pure subroutine dyad_solve_transposed(b, c1, cm, c2, f, y)
    real(wp), intent(in) :: b(:, :)
    integer, intent(in) :: c1, cm, c2
    type(small_factors_t), intent(in) :: f
    real(wp), intent(inout) :: y(:)
    real(wp) :: s(6), g(2), ym(2), rest(3)
    s = y(1:6)
    g(1) = dot_product(f%n(:, 1), s(1:3))
    g(2) = dot_product(f%n(:, 2), s(4:6))
    ! p^T ym = g
    ym = cramer2(f%p(1, 1), f%p(2, 1), f%p(1, 2), f%p(2, 2), g(1), g(2), f%det)
    y(cm:cm + 1) = ym
    rest = s(1:3) - b(cm, 1:3) * ym(1) - b(cm + 1, 1:3) * ym(2)
    call outer_multipliers(b, c1, 0, f%n(:, 1), f%pick(1), rest, y(c1:c1 + 1))
    rest = s(4:6) - b(cm, 4:6) * ym(1) - b(cm + 1, 4:6) * ym(2)
    call outer_multipliers(b, c2, 3, f%n(:, 2), f%pick(2), rest, y(c2:c2 + 1))
  end subroutine dyad_solve_transposed

  !> A solution x of the two rows c, c+1 of b on columns off+1..off+3 (rows x = r) with
  !> x(pick) = 0 (the other two columns' determinant is n(pick), n = the rows' cross
  !> product).
  pure subroutine particular(b, c, off, n, pick, r, x)
    real(wp), intent(in) :: b(:, :), n(3), r(2)
    integer, intent(in) :: c, off, pick
    real(wp), intent(out) :: x(3)
    integer :: j, k
    call others(pick, j, k)
    x(pick) = 0.0_wp
    x([j, k]) = cramer2(b(c, off + j), b(c, off + k), b(c + 1, off + j), b(c + 1, off + k), r(1), r(2), n(pick))
  end subroutine particular

  !> y with rows^T y = rest (rows: rows c, c+1 of b on columns off+1..off+3; 3 equations,
  !> consistent): the two other than `pick`.
  pure subroutine outer_multipliers(b, c, off, n, pick, rest, y)
    real(wp), intent(in) :: b(:, :), n(3), rest(3)
    integer, intent(in) :: c, off, pick
    real(wp), intent(out) :: y(2)
    integer :: j, k
    call others(pick, j, k)
    ! [rows(1,j) rows(2,j); rows(1,k) rows(2,k)] y = [rest(j); rest(k)], determinant n(pick)
    y = cramer2(b(c, off + j), b(c + 1, off + j), b(c, off + k), b(c + 1, off + k), rest(j), rest(k), n(pick))
  end subroutine outer_multipliers

end module kinetostat_linkage_small
