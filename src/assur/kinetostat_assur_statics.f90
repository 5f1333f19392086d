!> Generic mechanism, layer 2: the reactions of one class-II Assur group (dyad) from its
!> six equilibrium equations (manual section 5, Table 1: three per link), solved with LAPACK
!> through kinetostat_lapack's solve_dense (dgesv; dgecon near its threshold; ill-conditioned = dead position).
!>
!> Pairs: 1 = outer pair of link a, 2 = inner pair (a with b), 3 = outer pair of link b.
!> Unknowns: a revolute pair carries a force (Rx, Ry) and no moment; a prismatic pair
!> (frictionless) carries a force N*n normal to its sliding line (n = t turned by +90 deg)
!> and a reaction moment M about the pair's reference point.
!> Forces reported: pair 1 on link a from the earlier link, pair 2 on link a from link b,
!> pair 3 on link b from the earlier link.
module kinetostat_assur_statics
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_lapack, only: solve_dense
  use kinetostat_vec2, only: perp, cross, magnitude
  use kinetostat_assur_kinematics, only: kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp
  implicit none
  private
  public :: dyad_reactions_t, dyad_reactions, pair_is_prismatic

  !> Reactions of one dyad.
  type :: dyad_reactions_t
    !> Force of each pair (1: on a from earlier link, 2: on a from b, 3: on b from earlier), N.
    real(wp) :: f(2, 3) = 0.0_wp
    !> Signed normal force N along n = perp(t) of each prismatic pair (0 for revolute), N.
    real(wp) :: n(3) = 0.0_wp
    !> Reaction moment of each prismatic pair about its reference point (0 for revolute), N*m.
    real(wp) :: m(3) = 0.0_wp
  end type dyad_reactions_t

contains

  !> Whether pair `j` (1..3) of a dyad of kind `kind` is prismatic.
  pure logical function pair_is_prismatic(kind, j)
    !> Dyad kind code 1..5.
    integer, intent(in) :: kind
    !> Pair index: 1 outer of a, 2 inner, 3 outer of b.
    integer, intent(in) :: j
    select case (kind)
    case (kind_rrr)
      pair_is_prismatic = .false.
    case (kind_rrp)
      pair_is_prismatic = j == 3
    case (kind_rpr)
      pair_is_prismatic = j == 2
    case (kind_prp)
      pair_is_prismatic = j /= 2
    case (kind_rpp)
      pair_is_prismatic = j /= 1
    case default
      pair_is_prismatic = .false.
    end select
  end function pair_is_prismatic

  !> Solve the six equilibrium equations of a dyad in closed form (manual section 5: the
  !> group's force equations give the outer reactions from the inner one, so two equations
  !> in two unknowns remain). With r_j = p_j - o and F_a, M_a, F_b, M_b the known loads
  !> (moments about o):
  !>
  !>   link a:  F1 + F2 + F_a = 0,   r1 x F1 + M1 + r2 x F2 + M2 + M_a = 0
  !>   link b: -F2 + F3 + F_b = 0,  -r2 x F2 - M2 + r3 x F3 + M3 + M_b = 0
  !>
  !> (a prismatic pair j: F_j = N_j n_j with n_j = perp(t_j) and a couple M_j; a revolute
  !> one: M_j = 0). Per kind, with u1 = r2 - r1, u3 = r3 - r2, c1 = r1 x F_a - M_a and
  !> c3 = r3 x F_b - M_b:
  !>
  !> - RRR: u1 x F2 = c1, u3 x F2 = c3, so F2 = (c1 u3 - c3 u1) / (u1 x u3);
  !> - RRP: u1 x F2 = c1, t3 . F2 = t3 . F_b; N3 = n3 . (F2 - F_b), M3 from link b's moments;
  !> - RPR: N2 (u1 x n2) + M2 = c1, N2 (u3 x n2) - M2 = c3;
  !> - PRP: N1 n1 + N3 n3 = -(F_a + F_b); M1, M3 from each link's moments;
  !> - RPP: -N2 n2 + N3 n3 = -F_b; M2 from link a's moments, M3 from link b's;
  !>
  !> then F1 = -F_a - F2 and F3 = F2 - F_b. Where the 2x2's determinant is small (below
  !> closed_form_rel of its entries' scale, the largest |r_j| for lengths: near a dead
  !> position) the six equations are solved as one system instead (dense_reactions), which
  !> also decides whether the position is singular; `dense` asks for that solve whatever the
  !> determinant (the closed form's second opinion in the tests).
  pure subroutine dyad_reactions(kind, p, t, o, f_known, m_known, r, error, dense)
    !> Dyad kind code 1..5.
    integer, intent(in) :: kind
    !> Reference point of each pair, m.
    real(wp), intent(in) :: p(2, 3)
    !> Unit direction of the sliding line of each prismatic pair.
    real(wp), intent(in) :: t(2, 3)
    !> Point about which the known moments are taken, m.
    real(wp), intent(in) :: o(2)
    !> Known resultant forces on links a and b, N.
    real(wp), intent(in) :: f_known(2, 2)
    !> Known moments on links a and b about `o`, N*m.
    real(wp), intent(in) :: m_known(2)
    !> The reactions.
    type(dyad_reactions_t), intent(out) :: r
    !> Geometry error when the system is singular or ill-conditioned.
    type(error_t), allocatable, intent(out) :: error
    !> Solve the six equations as one dense system (default: false).
    logical, intent(in), optional :: dense
    !> A 2x2 whose |determinant| is at least this times the product of its columns' scales
    !> is solved in closed form: the six equations' reciprocal condition is then far above
    !> the dense solve's threshold (1e-12).
    real(wp), parameter :: closed_form_rel = 1.0e-6_wp
    real(wp) :: r1(2), r2(2), r3(2), u1(2), u3(2), fa(2), fb(2), c1, c3, det, len2, g(2)
    real(wp) :: n1(2), n2(2), n3(2), f2(2), k1, k3
    logical :: closed
    !> The kind solved in closed form (0: none, the dense solve).
    integer :: kind_closed
    kind_closed = kind
    r1 = p(:, 1) - o
    r2 = p(:, 2) - o
    r3 = p(:, 3) - o
    fa = f_known(:, 1)
    fb = f_known(:, 2)
    ! the squared length scale of the dyad (the dense solve's: the largest |r_j|, else 1)
    len2 = max(r1(1)**2 + r1(2)**2, r2(1)**2 + r2(2)**2, r3(1)**2 + r3(2)**2)
    if (.not. len2 > 0.0_wp) len2 = 1.0_wp
    closed = .false.
    if (present(dense)) then
      if (dense) kind_closed = 0
    end if
    select case (kind_closed)
    case (kind_rrr)
      u1 = r2 - r1
      u3 = r3 - r2
      det = cross(u1, u3)
      if (det**2 >= closed_form_rel**2 * len2**2) then
        closed = .true.
        c1 = cross(r1, fa) - m_known(1)
        c3 = cross(r3, fb) - m_known(2)
        f2 = (c1 * u3 - c3 * u1) / det
        r%f(:, 2) = f2
        r%f(:, 1) = -fa - f2
        r%f(:, 3) = f2 - fb
      end if
    case (kind_rrp)
      u1 = r2 - r1
      det = -dot_product(u1, t(:, 3))
      if (det**2 >= closed_form_rel**2 * len2) then
        closed = .true.
        c1 = cross(r1, fa) - m_known(1)
        ! rows perp(u1) . F2 = c1 and t3 . F2 = t3 . F_b
        c3 = dot_product(t(:, 3), fb)
        f2 = [c1 * t(2, 3) - u1(1) * c3, -u1(2) * c3 - t(1, 3) * c1] / det
        n3 = perp(t(:, 3))
        r%n(3) = dot_product(f2 - fb, n3)
        r%f(:, 3) = r%n(3) * n3
        r%m(3) = -m_known(2) + cross(r2, f2) - cross(r3, r%f(:, 3))
        r%f(:, 2) = f2
        r%f(:, 1) = -fa - f2
      end if
    case (kind_rpr)
      n2 = perp(t(:, 2))
      k1 = cross(r2 - r1, n2)
      k3 = cross(r3 - r2, n2)
      det = k1 + k3
      if (det**2 >= closed_form_rel**2 * len2) then
        closed = .true.
        c1 = cross(r1, fa) - m_known(1)
        c3 = cross(r3, fb) - m_known(2)
        r%n(2) = (c1 + c3) / det
        r%m(2) = c1 - r%n(2) * k1
        f2 = r%n(2) * n2
        r%f(:, 2) = f2
        r%f(:, 1) = -fa - f2
        r%f(:, 3) = f2 - fb
      end if
    case (kind_prp)
      n1 = perp(t(:, 1))
      n3 = perp(t(:, 3))
      det = cross(n1, n3)
      if (abs(det) >= closed_form_rel) then
        closed = .true.
        g = -(fa + fb)
        r%n(1) = cross(g, n3) / det
        r%n(3) = cross(n1, g) / det
        r%f(:, 1) = r%n(1) * n1
        r%f(:, 3) = r%n(3) * n3
        f2 = -fa - r%f(:, 1)
        r%f(:, 2) = f2
        r%m(1) = -m_known(1) - cross(r1, r%f(:, 1)) - cross(r2, f2)
        r%m(3) = -m_known(2) + cross(r2, f2) - cross(r3, r%f(:, 3))
      end if
    case (kind_rpp)
      n2 = perp(t(:, 2))
      n3 = perp(t(:, 3))
      ! columns -n2, n3, right-hand side -F_b
      det = -cross(n2, n3)
      if (abs(det) >= closed_form_rel) then
        closed = .true.
        r%n(2) = cross(-fb, n3) / det
        r%n(3) = cross(-n2, -fb) / det
        f2 = r%n(2) * n2
        r%f(:, 2) = f2
        r%f(:, 3) = r%n(3) * n3
        r%f(:, 1) = -fa - f2
        r%m(2) = -m_known(1) - cross(r1, r%f(:, 1)) - cross(r2, f2)
        r%m(3) = -m_known(2) + cross(r2, f2) + r%m(2) - cross(r3, r%f(:, 3))
      end if
    case default
      continue  ! the dense solve, asked for with `dense`
    end select
    if (.not. closed) call dense_reactions(kind, p, t, o, f_known, m_known, r, error)
  end subroutine dyad_reactions

  !> dyad_reactions' dense solve (arguments as there): the six equilibrium equations as one
  !> system (LU). Moment rows are divided by a length scale and the unknown moments
  !> multiplied by it, so the system is dimensionless.
  pure subroutine dense_reactions(kind, p, t, o, f_known, m_known, r, error)
    integer, intent(in) :: kind
    real(wp), intent(in) :: p(2, 3), t(2, 3), o(2), f_known(2, 2), m_known(2)
    type(dyad_reactions_t), intent(out) :: r
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: a(6, 6), b(6), x(6), scale, nrm(2)
    integer :: j, col, link, row
    real(wp), parameter :: sgn(2, 3) = reshape([1.0_wp, 0.0_wp, 1.0_wp, -1.0_wp, 0.0_wp, 1.0_wp], [2, 3])

    scale = 0.0_wp
    do j = 1, 3
      ! (o is usually one of the points: its distance 0 needs no hypot)
      if (any(p(:, j) /= o)) scale = max(scale, magnitude(p(:, j) - o))
    end do
    if (.not. scale > 0.0_wp) scale = 1.0_wp
    a = 0.0_wp
    do j = 1, 3
      col = 2 * j - 1
      do link = 1, 2
        if (sgn(link, j) == 0.0_wp) cycle
        row = 3 * link - 2
        if (pair_is_prismatic(kind, j)) then
          nrm = perp(t(:, j))
          a(row:row + 1, col) = sgn(link, j) * nrm
          a(row + 2, col) = sgn(link, j) * cross(p(:, j) - o, nrm) / scale
          a(row + 2, col + 1) = sgn(link, j)
        else
          a(row:row + 1, col) = sgn(link, j) * [1.0_wp, 0.0_wp]
          a(row:row + 1, col + 1) = sgn(link, j) * [0.0_wp, 1.0_wp]
          a(row + 2, col) = -sgn(link, j) * (p(2, j) - o(2)) / scale
          a(row + 2, col + 1) = sgn(link, j) * (p(1, j) - o(1)) / scale
        end if
      end do
    end do
    b(1:2) = -f_known(:, 1)
    b(3) = -m_known(1) / scale
    b(4:5) = -f_known(:, 2)
    b(6) = -m_known(2) / scale
    call solve_dense(a, b, x, error)
    if (allocated(error)) return
    do j = 1, 3
      col = 2 * j - 1
      if (pair_is_prismatic(kind, j)) then
        r%n(j) = x(col)
        r%m(j) = x(col + 1) * scale
        r%f(:, j) = x(col) * perp(t(:, j))
      else
        r%f(:, j) = x(col:col + 1)
      end if
    end do
  end subroutine dense_reactions

end module kinetostat_assur_statics
