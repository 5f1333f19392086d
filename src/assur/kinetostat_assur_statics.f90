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

  !> Solve the six equilibrium equations of a dyad.
  !> Known loads: resultant force `f_known(:,i)` on link i (a = 1, b = 2) and moment
  !> `m_known(i)` about the point `o` (N*m). Moment rows are divided by a length scale and
  !> the unknown moments multiplied by it, so the system is dimensionless.
  pure subroutine dyad_reactions(kind, p, t, o, f_known, m_known, r, error)
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
  end subroutine dyad_reactions

end module kinetostat_assur_statics
