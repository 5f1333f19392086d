!> Any planar linkage of lower pairs (`&linkage` decks): the kernel. Every moving link's pose
!> (x, y, theta of its reference point) is an unknown; each turning pair R gives two
!> constraint equations, each sliding pair P two (no relative turn, no motion across the
!> guide), each drive one (the relative angle of a turning pair, the stroke of a sliding
!> pair). With W = 3n - 2p5 equal to the number of drives the system is square: positions by
!> Newton's method from the previous step, velocities and accelerations by linear solves with
!> the same Jacobian J (factored once per pose: its factors serve the velocities, the
!> accelerations, the velocity analogues of the self-check and the next step's predictor,
!> kept with the poses they belong to in a `linkage_work_t`). The reactions twice, by two
!> formulations that share no equation: the Lagrange multipliers of the constraints, J^T
!> lambda = -Q (Q: the applied, gravity and inertia loads as generalised forces about each
!> link's reference point), one global system; and, as the self-check's second opinion, the
!> course's group method: each unit's links as free bodies (the pair forces at the joints as
!> unknowns, Newton-Euler about each centre of mass), the last group first, the input units
!> last, each with the forces of the groups solved before.
module kinetostat_linkage
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_lapack, only: solve_dense, factor_dense, solve_factored, trsm_table, lu_solve_transposed
  use kinetostat_vec2, only: perp, cross, fast_magnitude
  use kinetostat_linkage_types, only: linkage_t, linkage_link_t, linkage_pair_t, linkage_drive_t, linkage_force_t, &
    linkage_unit_t, pair_r, pair_p
  use kinetostat_linkage_closed, only: place_units, units_pairs, dyad_arms, point_position
  use kinetostat_linkage_constraints, only: linkage_rows, pair_row, drive_row, linkage_reference_pose, &
    link_point_state, set_turns, turned, position_cs, constraints, quadratic_terms
  use kinetostat_linkage_small, only: solve3, two_body_solve, small_factors_t, factor3, solve3_factored, dyad_factor, &
    dyad_solve, dyad_solve_transposed
  use kinetostat_linkage_dyads, only: dyad_plan_t, plan_dyads, dyad_velocities, dyad_accelerations, dyad_reactions
  use kinetostat_selfcheck, only: link_balance_t, balance_add_force, balance_add_couple, equilibrium_residual, &
    power_mismatch
  implicit none
  private
  public :: linkage_t, linkage_link_t, linkage_pair_t, linkage_drive_t, linkage_force_t, linkage_unit_t
  public :: linkage_step_t, linkage_work_t, pair_r, pair_p
  public :: linkage_rows, pair_row, drive_row, point_position, link_point_state
  public :: linkage_assemble, linkage_assemble_newton, linkage_motion, linkage_statics, linkage_reference_pose
  public :: linkage_fast_motion
  public :: linkage_worst_unit
  public :: linkage_velocity_analogues, linkage_free_body, linkage_reaction_gap

  !> Newton's method: largest number of iterations of one (sub)step.
  integer, parameter :: max_newton = 40
  !> Newton's method: converged when every constraint is below this times the linkage's size.
  real(wp), parameter :: newton_tol = 1.0e-12_wp
  !> Continuation: largest turn of a drive in one substep, rad (about 5 deg).
  real(wp), parameter :: max_substep_angle = 5.0_wp * pi / 180.0_wp
  !> Continuation: largest stroke of a drive in one substep, relative to the linkage's size.
  real(wp), parameter :: max_substep_stroke = 0.05_wp

  !> The results of one step.
  type :: linkage_step_t
    !> Poses (x, y, theta) of the links' reference points, their first and second time
    !> derivatives (3n each).
    real(wp), allocatable :: q(:), qd(:), qdd(:)
    !> Force on link a from link b of every pair (global), N.
    real(wp), allocatable :: f(:, :)
    !> Sliding pairs: normal force on a along the guide's normal (signed), N, and the couple
    !> on a, N*m (0 for turning pairs).
    real(wp), allocatable :: normal(:), couple(:)
    !> Effort of every drive on link a from b: moment (N*m) or force along the guide (N).
    real(wp), allocatable :: effort(:)
    !> Largest equilibrium residual of the links (kinetostat_selfcheck's rule).
    real(wp) :: residual = 0.0_wp
    !> Largest power-balance mismatch of the drives' efforts.
    real(wp) :: mismatch = 0.0_wp
    !> Largest difference of the Lagrange and the group method's reactions, relative to the
    !> step's largest reaction.
    real(wp) :: solver_gap = 0.0_wp
  end type linkage_step_t

  !> The workspace of a run of steps (no allocation per step): the Jacobian J of the last
  !> poses it was evaluated at, its LU factors and the velocity analogues from them. One
  !> workspace per linkage: J is kept by the poses it belongs to, not by the linkage.
  type :: linkage_work_t
    !> Constraints (rows) and the Jacobian (rows x 3n) at the poses q_jac.
    real(wp), allocatable :: phi(:), jac(:, :)
    !> The poses of jac.
    real(wp), allocatable :: q_jac(:)
    !> LU factors of jac and their row interchanges (valid when `factored`).
    real(wp), allocatable :: lu(:, :)
    integer, allocatable :: ipiv(:)
    !> Velocity analogues at q_jac (3n x drives; valid when `factored`).
    real(wp), allocatable :: v(:, :)
    !> J^T, its factors and row interchanges (the reactions).
    real(wp), allocatable :: jt(:, :), lut(:, :)
    integer, allocatable :: ipivt(:)
    !> A Newton correction or right-hand side (rows).
    real(wp), allocatable :: dx(:)
    !> dtrsm's rows of a factorisation of order 3n (kinetostat_lapack's trsm_table).
    integer, allocatable :: trsm(:, :)
    !> Drive values 0 (J does not depend on them); zeros of the poses' size.
    real(wp), allocatable :: dq0(:), zero_q(:)
    !> The group method: its system (at most 3n x 3n), factors, row interchanges and
    !> right-hand side.
    real(wp), allocatable :: fa(:, :), flu(:, :), fb(:)
    integer, allocatable :: fipiv(:)
    !> The group method: each link's own loads (force, moment about its centre of mass: 3 x
    !> n) and centre of mass (2 x n).
    real(wp), allocatable :: load(:, :), cm(:, :)
    !> The group method: each link's place in the unit being solved (0: not in it).
    integer, allocatable :: local(:)
    !> The group method: the pairs and drives whose reactions are known.
    logical, allocatable :: pair_known(:), drive_known(:)
    !> The group method's reactions (as linkage_step_t's f, normal, couple, effort).
    real(wp), allocatable :: f2(:, :), normal2(:), couple2(:), effort2(:)
    !> The generalised loads and the multipliers (rows).
    real(wp), allocatable :: gen(:), lam(:)
    !> Each link's centre of mass and its acceleration (2 x n) as generalised_loads found
    !> them (the self-check's equilibrium takes them from there).
    real(wp), allocatable :: s_cm(:, :), a_cm(:, :)
    !> Each link's balance (the self-check).
    type(link_balance_t), allocatable :: bal(:)
    !> cos and sin of each link's turn (2 x 0:n, column 0 the frame's) in the poses of the
    !> routine that set them last.
    real(wp), allocatable :: cs(:, :)
    !> Scratch of solve_j and solve_jt (rows) and of linkage_assemble (poses): no
    !> allocation per step.
    real(wp), allocatable :: rhs(:), unit_x(:), q_new(:)
    !> The poses of cs (valid when `has_cs`).
    real(wp), allocatable :: q_cs(:)
    logical :: has_cs = .false.
    !> jac holds J(q_jac); lu (or the units' factors) and v hold its factors and analogues.
    logical :: has_jac = .false., factored = .false.
    !> J is solved unit by unit (the units of the structural analysis partition its rows and
    !> columns: J is block triangular in their order); otherwise as one dense system.
    logical :: blocked = .false.
    !> Every unit is an input unit of one link or a dyad: the poses by closed forms.
    logical :: closed = .false.
    !> The dyads' arms for the closed forms (kinetostat_linkage_closed's dyad_arms).
    real(wp), allocatable :: arms(:, :)
    !> Each unit's pairs for the closed forms (kinetostat_linkage_closed's units_pairs).
    integer, allocatable :: pairs_of(:, :)
    !> Each unit's order (3 x its links), columns of J and trsm_table (largest order x units).
    integer, allocatable :: unit_order(:), unit_cols(:, :), unit_trsm(:, :, :)
    !> Each unit's diagonal block of J, its LU factors and row interchanges (a unit solved in
    !> closed form: the block itself).
    real(wp), allocatable :: unit_block(:, :), unit_lu(:, :, :)
    integer, allocatable :: unit_ipiv(:, :)
    !> Solve an input unit of one link and a dyad in closed form (kinetostat_linkage_small)
    !> where its determinants are clear of zero; false: every unit by its LU factors (the
    !> general solve the tests compare the closed forms with).
    logical :: small_solves = .true.
    !> Each unit solved in closed form at the poses of the factors; its factors.
    logical, allocatable :: unit_small(:)
    type(small_factors_t), allocatable :: unit_fac(:)
    !> A dyad's rows (unit_rows' places) of the outer pair of its first link, the inner pair
    !> and the outer pair of its second link (the first of each pair's two; 0: no dyad).
    integer, allocatable :: unit_dyad(:, :)
    !> J by its rows' links (every constraint row involves two links: a pair's, a drive's
    !> pair's): row r is je(:, 1, r) on the columns of link jl(1, r) plus je(:, 2, r) on those
    !> of jl(2, r) (0: the frame, no columns). The solves unit by unit with small_solves
    !> take J from these (no dense J: its off-block products over the rows' two links only).
    integer, allocatable :: jl(:, :)
    real(wp), allocatable :: je(:, :, :)
    !> The place of link jl(slot, r) among the links of the unit of row r (0: the frame, or
    !> a link of a unit before).
    integer, allocatable :: jl_place(:, :)
    !> Each link's rows of J in increasing order (link_row(1:link_deg(i), i)) and the slot
    !> (1, 2) of jl that names it.
    integer, allocatable :: link_row(:, :), link_slot(:, :), link_deg(:)
    !> Every unit an input unit of one link or a dyad (`closed`): the velocities,
    !> accelerations and velocity analogues from the points (kinetostat_linkage_dyads, no J)
    !> and the reactions by the group method's closed forms; false: by J (the general solve
    !> the tests compare with).
    logical :: fast = .true.
    !> The units' links and pairs and the dyads' 2 x 2 systems (kinetostat_linkage_dyads).
    type(dyad_plan_t) :: plan
    !> v holds the velocity analogues of the poses q_fast from the points (valid when
    !> has_fast).
    real(wp), allocatable :: q_fast(:)
    logical :: has_fast = .false.
    !> The steps whose reactions the fast path solved with this workspace (the first is also
    !> solved by the Lagrange multipliers: solver_gap).
    integer :: fast_statics = 0
    !> A drive's unit rate (scratch, drives).
    real(wp), allocatable :: rate(:)
  end type linkage_work_t

contains

  !> Allocates the workspace for `mech` (once).
  pure subroutine work_ready(mech, work)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> The workspace, allocated for it.
    type(linkage_work_t), intent(inout) :: work
    integer :: nr
    nr = linkage_rows(mech)
    if (allocated(work%jac)) then
      if (size(work%jac, 1) == nr .and. size(work%v, 2) == size(mech%drives) .and. &
          size(work%f2, 2) == size(mech%pairs)) return
      deallocate (work%phi, work%jac, work%q_jac, work%lu, work%ipiv, work%v, work%jt, work%lut, work%ipivt, work%dx, &
                  work%dq0, work%zero_q, work%trsm)
      deallocate (work%fa, work%flu, work%fb, work%fipiv, work%load, work%cm, work%local, work%pair_known, &
                  work%drive_known, work%f2, work%normal2, work%couple2, work%effort2, work%gen, work%lam, work%bal, work%cs, &
                  work%q_cs, work%rhs, work%unit_x, work%q_new, work%s_cm, work%a_cm, work%q_fast, work%rate)
      deallocate (work%jl, work%je, work%link_row, work%link_slot, work%link_deg)
    end if
    allocate (work%fa(nr, nr), work%flu(nr, nr), work%fb(nr), work%fipiv(nr), work%load(3, size(mech%links)), &
              work%cm(2, size(mech%links)), work%local(size(mech%links)), work%pair_known(size(mech%pairs)), &
              work%drive_known(size(mech%drives)), work%f2(2, size(mech%pairs)), work%normal2(size(mech%pairs)), &
              work%couple2(size(mech%pairs)), work%effort2(size(mech%drives)), work%gen(nr), work%lam(nr), &
              work%bal(size(mech%links)), work%cs(2, 0:size(mech%links)), work%q_cs(3 * size(mech%links)), &
              work%s_cm(2, size(mech%links)), work%a_cm(2, size(mech%links)))
    allocate (work%phi(nr), work%jac(nr, nr), work%q_jac(nr), work%lu(nr, nr), work%ipiv(nr), &
              work%v(nr, size(mech%drives)), work%jt(nr, nr), work%lut(nr, nr), work%ipivt(nr), work%dx(nr))
    allocate (work%dq0(size(mech%drives)), work%zero_q(nr), work%rhs(nr), work%unit_x(nr), &
              work%q_new(3 * size(mech%links)), work%q_fast(3 * size(mech%links)), work%rate(size(mech%drives)), &
              source=0.0_wp)
    work%trsm = trsm_table(nr)
    call rows_ready(mech, work)
    work%has_jac = .false.
    work%factored = .false.
    work%has_cs = .false.
    work%has_fast = .false.
    call units_ready(mech, work)
  end subroutine work_ready

  !> The links of J's rows (work%jl: a turning pair's rows on its links a and b, a sliding
  !> pair's and a drive's on the block and the guide) and each link's rows.
  pure subroutine rows_ready(mech, work)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(inout) :: work
    integer :: k, r, d, nr, i, slot
    nr = linkage_rows(mech)
    allocate (work%jl(2, nr), source=0)
    allocate (work%je(3, 2, nr), source=0.0_wp)
    do k = 1, size(mech%pairs)
      r = pair_row(k)
      work%jl(:, r) = row_links(mech%pairs(k))
      work%jl(:, r + 1) = work%jl(:, r)
    end do
    do d = 1, size(mech%drives)
      work%jl(:, drive_row(mech, d)) = row_links(mech%pairs(mech%drives(d)%pair))
    end do
    allocate (work%link_deg(size(mech%links)), source=0)
    do r = 1, nr
      do slot = 1, 2
        if (work%jl(slot, r) > 0) work%link_deg(work%jl(slot, r)) = work%link_deg(work%jl(slot, r)) + 1
      end do
    end do
    allocate (work%link_row(max(1, maxval(work%link_deg)), size(mech%links)), &
              work%link_slot(max(1, maxval(work%link_deg)), size(mech%links)), source=0)
    work%link_deg(:) = 0
    do r = 1, nr
      do slot = 1, 2
        i = work%jl(slot, r)
        if (i == 0) cycle
        work%link_deg(i) = work%link_deg(i) + 1
        work%link_row(work%link_deg(i), i) = r
        work%link_slot(work%link_deg(i), i) = slot
      end do
    end do
  contains
    !> The two links of a pair's rows: a and b (R), the block and the guide (P).
    pure function row_links(pr) result(lk)
      type(linkage_pair_t), intent(in) :: pr
      integer :: lk(2)
      if (pr%kind == pair_r) then
        lk = [pr%a, pr%b]
      else
        lk = [pr%a + pr%b - pr%guide, pr%guide]
      end if
    end function row_links
  end subroutine rows_ready

  !> J by its rows' links (work%je) with the small solves (unit by unit, small_solves); the
  !> dense J otherwise (the general solve).
  pure logical function by_rows(work)
    type(linkage_work_t), intent(in) :: work
    by_rows = work%blocked .and. work%small_solves
  end function by_rows

  !> The constraints phi(q) for drive values dq into work%phi and their Jacobian (work%je, and
  !> work%jac unless by_rows), with the turns of q in work%cs.
  pure subroutine work_constraints(mech, q, dq, work)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), dq(:)
    type(linkage_work_t), intent(inout) :: work
    integer :: r, slot, i
    call constraints(mech, q, dq, work%phi, work%je, work%cs)
    if (by_rows(work)) return
    work%jac(:, :) = 0.0_wp
    do r = 1, size(work%jl, 2)
      do slot = 1, 2
        i = work%jl(slot, r)
        if (i > 0) work%jac(r, 3 * i - 2:3 * i) = work%jac(r, 3 * i - 2:3 * i) + work%je(:, slot, r)
      end do
    end do
  end subroutine work_constraints

  !> The unit-by-unit solve of J (work%blocked) when the units partition J's rows and each
  !> unit's rows are as many as its links' coordinates (every validated deck; a linkage
  !> built without its structure is solved densely).
  pure subroutine units_ready(mech, work)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(inout) :: work
    integer, allocatable :: owner(:)
    integer :: u, nu, mx, nr, i, k, slot
    work%blocked = .false.
    work%closed = .false.
    if (allocated(work%unit_order)) deallocate (work%unit_order, work%unit_cols, work%unit_trsm, work%unit_block, &
                                                work%unit_lu, work%unit_ipiv, work%unit_small, work%unit_fac, &
                                                work%unit_dyad, work%arms, work%jl_place)
    if (allocated(work%pairs_of)) deallocate (work%pairs_of)
    if (.not. allocated(mech%units)) return
    nu = size(mech%units)
    if (nu == 0) return
    nr = linkage_rows(mech)
    allocate (owner(nr), source=0)
    mx = 0
    do u = 1, nu
      associate (unit => mech%units(u))
        if (.not. allocated(unit%rows) .or. .not. allocated(unit%links)) return
        if (size(unit%rows) /= 3 * size(unit%links)) return
        do i = 1, size(unit%rows)
          if (unit%rows(i) < 1 .or. unit%rows(i) > nr) return
          if (owner(unit%rows(i)) /= 0) return
          owner(unit%rows(i)) = u
        end do
        mx = max(mx, size(unit%rows))
      end associate
    end do
    if (any(owner == 0)) return
    allocate (work%unit_order(nu), work%unit_cols(mx, nu), work%unit_trsm(mx, mx, nu), source=0)
    allocate (work%unit_block(mx, mx), work%unit_lu(mx, mx, nu), source=0.0_wp)
    allocate (work%unit_ipiv(mx, nu), work%unit_dyad(3, nu), source=0)
    allocate (work%unit_small(nu), source=.false.)
    allocate (work%unit_fac(nu))
    do u = 1, nu
      k = size(mech%units(u)%rows)
      work%unit_order(u) = k
      work%unit_cols(1:k, u) = unit_columns(mech%units(u))
      work%unit_trsm(1:k, 1:k, u) = trsm_table(k)
      work%unit_dyad(:, u) = dyad_rows(mech, mech%units(u))
    end do
    work%arms = dyad_arms(mech)
    work%pairs_of = units_pairs(mech)
    allocate (work%jl_place(2, nr), source=0)
    do u = 1, nu
      do i = 1, size(mech%units(u)%rows)
        k = mech%units(u)%rows(i)
        do slot = 1, 2
          if (work%jl(slot, k) > 0) work%jl_place(slot, k) = findloc(mech%units(u)%links, work%jl(slot, k), 1)
        end do
      end do
    end do
    work%blocked = .true.
    work%closed = all(mech%units%class == 2 .or. (mech%units%class == 1 .and. work%unit_order == 3))
    if (work%closed) call plan_dyads(mech, work%plan)
  end subroutine units_ready

  !> The fast path applies (`fast`, every unit an input unit of one link or a dyad with its
  !> plan, the small solves on).
  pure logical function use_fast(work)
    type(linkage_work_t), intent(in) :: work
    use_fast = work%fast .and. work%closed .and. work%small_solves
    if (use_fast) use_fast = work%plan%ok
  end function use_fast

  !> The velocity analogues of poses q from the points into work%v (unless it holds them);
  !> ok false where a dyad's 2 x 2 is near a zero determinant (then J decides).
  pure subroutine fast_analogues(mech, q, work, ok)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:)
    type(linkage_work_t), intent(inout) :: work
    logical, intent(out) :: ok
    ok = .true.
    if (work%has_fast) then
      if (same_poses(work%q_fast, q)) return
    end if
    call work_turns(work, q)
    call points_analogues(mech, q, work, ok)
  end subroutine fast_analogues

  !> fast_analogues at poses q whose turns work%cs holds, whatever work%v holds.
  pure subroutine points_analogues(mech, q, work, ok)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:)
    type(linkage_work_t), intent(inout) :: work
    logical, intent(out) :: ok
    integer :: d, n3
    work%has_fast = .false.
    n3 = size(q)
    do d = 1, size(mech%drives)
      work%rate(:) = 0.0_wp
      work%rate(d) = 1.0_wp
      call dyad_velocities(mech, work%plan, q, work%cs, work%rate, work%v(1:n3, d), ok)
      if (.not. ok) return
    end do
    work%q_fast(:) = q
    work%has_fast = .true.
  end subroutine points_analogues

  !> Factors J (work%jac): each unit's diagonal block, or the whole J densely. An error: a
  !> block (J) is singular or ill-conditioned (factor_dense's verdict).
  pure subroutine factor_j(mech, work, error)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    integer :: u, k, i, j
    if (.not. work%blocked) then
      call factor_dense(work%jac, work%lu, work%ipiv, error, work%trsm)
      return
    end if
    do u = 1, size(mech%units)
      k = work%unit_order(u)
      if (by_rows(work)) then
        call unit_block_by_rows(mech%units(u), work, k)
      else
        associate (rows => mech%units(u)%rows, cols => work%unit_cols(:, u))
          do j = 1, k
            do i = 1, k
              work%unit_block(i, j) = work%jac(rows(i), cols(j))
            end do
          end do
        end associate
      end if
      work%unit_small(u) = .false.
      if (work%small_solves) then
        associate (dy => work%unit_dyad(:, u))
          if (k == 3 .and. size(mech%units(u)%links) == 1) then
            call factor3(work%unit_block(1:3, 1:3), work%unit_fac(u), work%unit_small(u))
          else if (k == 6 .and. dy(1) > 0) then
            call dyad_factor(work%unit_block(1:6, 1:6), dy(1), dy(2), dy(3), work%unit_fac(u), work%unit_small(u))
          end if
        end associate
        if (work%unit_small(u)) then
          work%unit_lu(1:k, 1:k, u) = work%unit_block(1:k, 1:k)
          cycle
        end if
      end if
      call factor_dense(work%unit_block(1:k, 1:k), work%unit_lu(1:k, 1:k, u), work%unit_ipiv(1:k, u), error, &
                        work%unit_trsm(1:k, 1:k, u))
      if (allocated(error)) return
    end do
  end subroutine factor_j

  !> Unit `unit`'s diagonal block of J (its rows, its links' columns: order k) into
  !> work%unit_block from J by its rows' links.
  pure subroutine unit_block_by_rows(unit, work, k)
    type(linkage_unit_t), intent(in) :: unit
    type(linkage_work_t), intent(inout) :: work
    integer, intent(in) :: k
    integer :: i, r, slot, e
    work%unit_block(1:k, 1:k) = 0.0_wp
    do i = 1, k
      r = unit%rows(i)
      do slot = 1, 2
        e = work%jl_place(slot, r)
        if (e > 0) work%unit_block(i, 3 * e - 2:3 * e) = work%je(:, slot, r)
      end do
    end do
  end subroutine unit_block_by_rows

  !> x = J^-1 x with factor_j's factors (x: constraint rows in, pose coordinates out): the
  !> units in their order, each with the coordinates of the units before it known.
  pure subroutine solve_j(mech, work, x, rhs, unit_x)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(in) :: work
    real(wp), intent(inout) :: x(:)
    !> Scratch (work%rhs, work%unit_x).
    real(wp), intent(out) :: rhs(:), unit_x(:)
    real(wp) :: s
    integer :: u, k, i, r
    if (.not. work%blocked) then
      call solve_factored(work%lu, work%ipiv, x)
      return
    end if
    rhs(:) = x
    x(:) = 0.0_wp
    do u = 1, size(mech%units)
      k = work%unit_order(u)
      do i = 1, k
        r = mech%units(u)%rows(i)
        s = rhs(r)
        call take_products(work, r, x, .false., s)
        unit_x(i) = s
      end do
      call unit_solve(work, u, unit_x(1:k), .false.)
      do i = 1, k
        x(work%unit_cols(i, u)) = unit_x(i)
      end do
    end do
  end subroutine solve_j

  !> x = J^-T x with factor_j's factors (x: generalised loads in, multipliers of the rows
  !> out): the units from the last, each with the multipliers of the units after it known.
  pure subroutine solve_jt(mech, work, x, rhs, unit_x)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(in) :: work
    real(wp), intent(inout) :: x(:)
    !> Scratch (work%rhs, work%unit_x).
    real(wp), intent(out) :: rhs(:), unit_x(:)
    real(wp) :: s
    integer :: u, k, i, c
    rhs(:) = x
    x(:) = 0.0_wp
    do u = size(mech%units), 1, -1
      k = work%unit_order(u)
      do i = 1, k
        c = work%unit_cols(i, u)
        s = rhs(c)
        call take_products(work, c, x, .true., s)
        unit_x(i) = s
      end do
      call unit_solve(work, u, unit_x(1:k), .true.)
      do i = 1, k
        x(mech%units(u)%rows(i)) = unit_x(i)
      end do
    end do
  end subroutine solve_jt

  !> s - (row i of J) . x, the terms in the columns' order; `transposed`: s - (column i of
  !> J) . x, in the rows' order. With by_rows by the row's two links' columns (the column's
  !> link's rows): the dense sum's terms in its order, so the same digits.
  pure subroutine take_products(work, i, x, transposed, s)
    type(linkage_work_t), intent(in) :: work
    integer, intent(in) :: i
    real(wp), intent(in) :: x(:)
    logical, intent(in) :: transposed
    real(wp), intent(inout) :: s
    integer :: c, slot, lo, e, m, j, r
    if (.not. by_rows(work)) then
      if (transposed) then
        do r = 1, size(x)
          s = s - work%jac(r, i) * x(r)
        end do
      else
        do c = 1, size(x)
          s = s - work%jac(i, c) * x(c)
        end do
      end if
    else if (transposed) then
      e = (i + 2) / 3
      m = i - 3 * e + 3
      do j = 1, work%link_deg(e)
        r = work%link_row(j, e)
        s = s - work%je(m, work%link_slot(j, e), r) * x(r)
      end do
    else
      lo = 1
      if (work%jl(2, i) < work%jl(1, i)) lo = 2
      do slot = lo, 3 - lo, 3 - 2 * lo
        e = work%jl(slot, i)
        if (e == 0) cycle
        s = s - work%je(1, slot, i) * x(3 * e - 2)
        s = s - work%je(2, slot, i) * x(3 * e - 1)
        s = s - work%je(3, slot, i) * x(3 * e)
      end do
    end if
  end subroutine take_products

  !> x = B^-1 x (B^-T x: `transposed`) for unit u's diagonal block B of J, with factor_j's
  !> factors: closed forms or LU.
  pure subroutine unit_solve(work, u, x, transposed)
    type(linkage_work_t), intent(in) :: work
    integer, intent(in) :: u
    real(wp), intent(inout) :: x(:)
    logical, intent(in) :: transposed
    integer :: k
    k = work%unit_order(u)
    if (work%unit_small(u)) then
      if (k == 3) then
        call solve3_factored(work%unit_fac(u), x, transposed)
      else
        associate (dy => work%unit_dyad(:, u))
          if (transposed) then
            call dyad_solve_transposed(work%unit_lu(1:6, 1:6, u), dy(1), dy(2), dy(3), work%unit_fac(u), x)
          else
            call dyad_solve(work%unit_lu(1:6, 1:6, u), dy(1), dy(2), dy(3), work%unit_fac(u), x)
          end if
        end associate
      end if
    else if (transposed) then
      call lu_solve_transposed(work%unit_lu(1:k, 1:k, u), work%unit_ipiv(1:k, u), x)
    else
      call solve_factored(work%unit_lu(1:k, 1:k, u), work%unit_ipiv(1:k, u), x)
    end if
  end subroutine unit_solve

  !> A dyad's places in its unit's rows (dyad_factor's c1, cm, c2): the outer pair of its
  !> first link, the inner pair, the outer pair of its second link; 0 when the unit is no
  !> dyad of three pairs with its two rows each in turn.
  pure function dyad_rows(mech, unit) result(c)
    type(linkage_t), intent(in) :: mech
    type(linkage_unit_t), intent(in) :: unit
    integer :: c(3)
    integer :: i, k, la, lb
    c = 0
    if (unit%class /= 2 .or. size(unit%links) /= 2 .or. size(unit%rows) /= 6) return
    do i = 1, 5, 2
      if (unit%rows(i) > 2 * size(mech%pairs) .or. mod(unit%rows(i), 2) == 0 .or. &
          unit%rows(i + 1) /= unit%rows(i) + 1) then
        c = 0
        return
      end if
      k = (unit%rows(i) + 1) / 2
      la = findloc(unit%links, mech%pairs(k)%a, 1)
      lb = findloc(unit%links, mech%pairs(k)%b, 1)
      if (mech%pairs(k)%a == 0) la = 0
      if (mech%pairs(k)%b == 0) lb = 0
      if (la > 0 .and. lb > 0) then
        c(2) = i
      else if (max(la, lb) == 1) then
        c(1) = i
      else if (max(la, lb) == 2) then
        c(3) = i
      end if
    end do
    if (any(c == 0)) c = 0
  end function dyad_rows

  !> J at poses q in `work` (evaluated unless it holds them), factored, with the velocity
  !> analogues (column d: dq/d(drive d), the other drives held). An error: J is singular.
  pure subroutine work_factored(mech, q, work, error)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses.
    real(wp), intent(in) :: q(:)
    !> The workspace: J, its factors and analogues at q.
    type(linkage_work_t), intent(inout) :: work
    !> Set when J is singular or ill-conditioned (factor_dense's verdict).
    type(error_t), allocatable, intent(out) :: error
    integer :: d
    call work_ready(mech, work)
    if (work%has_jac) then
      ! (the factors of the same poses are reused)
      if (any(work%q_jac /= q)) work%has_jac = .false.
    end if
    if (.not. work%has_jac) then
      ! J does not depend on the drive values (they enter the constraints only)
      call work_turns(work, q)
      call work_constraints(mech, q, work%dq0, work)
      work%q_jac(:) = q
      work%has_jac = .true.
      work%factored = .false.
    end if
    if (work%factored) return
    call factor_j(mech, work, error)
    if (allocated(error)) return
    do d = 1, size(mech%drives)
      work%v(:, d) = 0.0_wp
      work%v(drive_row(mech, d), d) = 1.0_wp
      call solve_j(mech, work, work%v(:, d), work%rhs, work%unit_x)
    end do
    work%factored = .true.
  end subroutine work_factored

  !> The poses a and b are the same numbers (a loop that stops at the first difference: the
  !> workspace's checks, several a step).
  pure logical function same_poses(a, b)
    real(wp), intent(in) :: a(:), b(:)
    integer :: i
    same_poses = .false.
    do i = 1, size(b)
      if (a(i) /= b(i)) return
    end do
    same_poses = .true.
  end function same_poses

  !> work%cs: the turns of poses q (set_turns), unless it holds them.
  pure subroutine work_turns(work, q)
    type(linkage_work_t), intent(inout) :: work
    real(wp), intent(in) :: q(:)
    if (work%has_cs) then
      if (same_poses(work%q_cs, q)) return
    end if
    call set_turns(q, work%cs)
    work%q_cs(:) = q
    work%has_cs = .true.
  end subroutine work_turns

  !> Assembles the linkage for drive values `dq` from the poses `q` (updated) at the drive
  !> values `dq_from`, walking there in substeps. Every unit an input unit of one link or a
  !> dyad: by the closed forms of place_units, each substep on the branch nearest to the
  !> substep before (the one Newton's method from there converges to), J factored at the
  !> result; otherwise, or where a closed form has no position or J is singular, by Newton's
  !> method (linkage_assemble_newton) with a first-order predictor. `error` gives the reason
  !> and the unit whose Jacobian is the worst conditioned ("... in group III(2,3,4,5)"; the
  !> caller names the step). `work` keeps J at the assembled poses (for linkage_motion and
  !> linkage_statics).
  pure subroutine linkage_assemble(mech, dq_from, dq, q, work, error)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Drive values of the poses q and the wanted ones, rad or m.
    real(wp), intent(in) :: dq_from(:), dq(:)
    !> Poses: in, assembled at dq_from; out, at dq.
    real(wp), intent(inout) :: q(:)
    !> Workspace (J and its factors at the last poses).
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    logical :: placed
    call work_ready(mech, work)
    if (work%closed) then
      call place_closed(mech, dq_from, dq, q, work, placed)
      if (placed) then
        if (use_fast(work)) then
          ! the velocity analogues from the points (no J): their 2 x 2 systems clear of a
          ! zero determinant, or J decides below
          call fast_analogues(mech, work%q_new, work, placed)
          if (placed) then
            q(:) = work%q_new
            return
          end if
        end if
        call work_factored(mech, work%q_new, work, error)
        if (.not. allocated(error)) then
          q(:) = work%q_new
          return
        end if
        deallocate (error)
      end if
    end if
    call linkage_assemble_newton(mech, dq_from, dq, q, work, error)
  end subroutine linkage_assemble

  !> The closed forms' placing (every unit an input unit of one link or a dyad): work%q_new
  !> the poses at drive values dq from poses q at dq_from, by place_units in substeps, each
  !> on the branch nearest to the substep before; work%cs their turns. placed false where a
  !> closed form has no position.
  pure subroutine place_closed(mech, dq_from, dq, q, work, placed)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: dq_from(:), dq(:), q(:)
    type(linkage_work_t), intent(inout) :: work
    logical, intent(out) :: placed
    integer :: m, s
    m = substeps(mech, dq_from, dq)
    ! (the turns' cos and sin go with the poses: place_units updates them as it places)
    call work_turns(work, q)
    work%has_cs = .false.
    work%q_new(:) = q
    placed = .true.
    do s = 1, m - 1
      call place_units(mech, dq_from + (dq - dq_from) * (real(s, wp) / real(m, wp)), work%q_new, placed, work%cs, &
                       work%arms, work%pairs_of)
      if (.not. placed) return
    end do
    call place_units(mech, dq, work%q_new, placed, work%cs, work%arms, work%pairs_of)
    if (.not. placed) return
    work%q_cs(:) = work%q_new
    work%has_cs = .true.
  end subroutine place_closed

  !> A step of the fast path in one pass (every unit an input unit of one link or a dyad):
  !> linkage_assemble's closed forms, then linkage_motion's velocities and accelerations from
  !> the points, without their checks of which poses the workspace holds. q: in, the poses at
  !> drive values dq_from; out, at dq; qd, qdd their velocities and accelerations for the
  !> drives' rates dv and accelerations da. done false (q, qd and qdd as they came): not a
  !> step for the fast path (another kind of unit, a closed form without a position, a 2 x 2
  !> near a zero determinant): linkage_assemble and linkage_motion decide.
  pure subroutine linkage_fast_motion(mech, dq_from, dq, dv, da, q, qd, qdd, work, done)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Drive values of the poses q and the wanted ones, rad or m.
    real(wp), intent(in) :: dq_from(:), dq(:)
    !> Drive rates and accelerations (rad/s, rad/s^2 or m/s, m/s^2).
    real(wp), intent(in) :: dv(:), da(:)
    !> Poses: in, assembled at dq_from; out, at dq.
    real(wp), intent(inout) :: q(:)
    !> Velocities and accelerations of the poses.
    real(wp), intent(inout) :: qd(:), qdd(:)
    !> Workspace.
    type(linkage_work_t), intent(inout) :: work
    !> The step was solved here.
    logical, intent(out) :: done
    integer :: d
    done = .false.
    call work_ready(mech, work)
    if (.not. use_fast(work)) return
    call place_closed(mech, dq_from, dq, q, work, done)
    if (done) call points_analogues(mech, work%q_new, work, done)
    if (.not. done) return
    q(:) = work%q_new
    qd = 0.0_wp
    do d = 1, size(mech%drives)
      qd = qd + work%v(1:size(q), d) * dv(d)
    end do
    call dyad_accelerations(mech, work%plan, q, work%cs, qd, da, qdd)
  end subroutine linkage_fast_motion

  !> The number of substeps from drive values dq_from to dq (a turn of at most
  !> max_substep_angle, a stroke of at most max_substep_stroke of the linkage's size each).
  pure integer function substeps(mech, dq_from, dq) result(m)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: dq_from(:), dq(:)
    real(wp) :: span
    integer :: d
    span = 0.0_wp
    do d = 1, size(dq)
      if (mech%pairs(mech%drives(d)%pair)%kind == pair_r) then
        span = max(span, abs(dq(d) - dq_from(d)) / max_substep_angle)
      else
        span = max(span, abs(dq(d) - dq_from(d)) / (max_substep_stroke * mech%size))
      end if
    end do
    m = max(1, ceiling(span))
  end function substeps

  !> Newton's method (linkage_assemble's where it has no closed form, and the second,
  !> independent solve the tests compare the closed forms with): the poses for drive values
  !> `dq` from the poses `q` (updated), walking there in substeps from the drive values
  !> `dq_from` of `q` with a first-order predictor.
  pure subroutine linkage_assemble_newton(mech, dq_from, dq, q, work, error, tol)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: dq_from(:), dq(:)
    real(wp), intent(inout) :: q(:)
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    !> Converged when every constraint is below tol times the linkage's size (newton_tol).
    real(wp), intent(in), optional :: tol
    real(wp) :: target(size(dq)), from(size(dq)), q_good(size(q)), limit
    integer :: m, s, it, d
    logical :: converged
    limit = newton_tol * mech%size
    if (present(tol)) limit = tol * mech%size
    m = substeps(mech, dq_from, dq)
    from(:) = dq_from
    q_good(:) = q
    do s = 1, m
      target = dq_from + (dq - dq_from) * (real(s, wp) / real(m, wp))
      ! predictor: the velocity analogues of the drives at the last assembled pose
      call work_factored(mech, q, work, error)
      if (allocated(error)) then
        call fatal_error(error, exit_geometry, fail_text("the Jacobian is singular (a dead position)"))
        return
      end if
      ! (explicit loops, not matmul: its library and inlined forms sum in different orders)
      do d = 1, size(dq)
        q = q + work%v(:, d) * (target(d) - from(d))
      end do
      converged = .false.
      do it = 1, max_newton
        call work_turns(work, q)
        call work_constraints(mech, q, target, work)
        work%q_jac(:) = q
        work%has_jac = .true.
        work%factored = .false.
        converged = maxval(abs(work%phi)) <= limit
        if (converged) exit
        call factor_j(mech, work, error)
        if (allocated(error)) then
          call fatal_error(error, exit_geometry, fail_text("the Jacobian is singular (a dead position)"))
          return
        end if
        work%dx(:) = -work%phi
        call solve_j(mech, work, work%dx, work%rhs, work%unit_x)
        q = q + work%dx
      end do
      if (.not. converged) then
        call fatal_error(error, exit_geometry, fail_text("Newton's method does not converge (the linkage cannot be assembled)"))
        return
      end if
      from = target
      q_good = q
    end do
  contains
    pure function fail_text(reason) result(text)
      character(*), intent(in) :: reason
      character(len=:), allocatable :: text
      text = reason//" in "//unit_name(mech, linkage_worst_unit(mech, q_good))
    end function fail_text
  end subroutine linkage_assemble_newton

  !> The unit ("group III(2,3,4,5)") by name for messages.
  pure function unit_name(mech, u) result(text)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: u
    character(len=:), allocatable :: text
    if (u < 1) then
      text = "the linkage"
    else if (mech%units(u)%class == 1) then
      text = "input unit "//mech%units(u)%label
    else
      text = "group "//mech%units(u)%label
    end if
  end function unit_name

  !> The unit whose diagonal block of J (its rows, its links' columns) is the worst
  !> conditioned in pose q: the block-triangular J is singular where one of them is.
  pure integer function linkage_worst_unit(mech, q)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses.
    real(wp), intent(in) :: q(:)
    real(wp), allocatable :: x(:), dq(:)
    real(wp) :: rc, worst
    type(error_t), allocatable :: err
    type(linkage_work_t) :: work
    integer, allocatable :: cols(:)
    integer :: u, i
    allocate (dq(size(mech%drives)))
    do i = 1, size(mech%drives)
      dq(i) = mech%drives(i)%q_ref
    end do
    ! (the dense J)
    work%small_solves = .false.
    call work_ready(mech, work)
    call work_turns(work, q)
    call work_constraints(mech, q, dq, work)
    linkage_worst_unit = 0
    if (.not. allocated(mech%units)) return
    worst = huge(1.0_wp)
    do u = 1, size(mech%units)
      cols = unit_columns(mech%units(u))
      allocate (x(size(cols)))
      call solve_dense(work%jac(mech%units(u)%rows, cols), [(1.0_wp, i=1, size(cols))], x, err, rc)
      if (allocated(err)) rc = 0.0_wp
      deallocate (x)
      if (rc < worst) then
        worst = rc
        linkage_worst_unit = u
      end if
    end do
  end function linkage_worst_unit

  !> Columns of J of a unit's links.
  pure function unit_columns(unit) result(cols)
    type(linkage_unit_t), intent(in) :: unit
    integer, allocatable :: cols(:)
    integer :: i
    allocate (cols(3 * size(unit%links)))
    do i = 1, size(unit%links)
      cols(3 * i - 2:3 * i) = [3 * unit%links(i) - 2, 3 * unit%links(i) - 1, 3 * unit%links(i)]
    end do
  end function unit_columns

  !> Velocity analogues: column d is dq/d(drive d) with the other drives held (3n x drives).
  pure subroutine linkage_velocity_analogues(mech, q, v, error)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses.
    real(wp), intent(in) :: q(:)
    !> The analogues.
    real(wp), intent(out) :: v(:, :)
    type(error_t), allocatable, intent(out) :: error
    type(linkage_work_t) :: work
    v = 0.0_wp
    call work_factored(mech, q, work, error)
    if (allocated(error)) return
    v = work%v
  end subroutine linkage_velocity_analogues

  !> Velocities and accelerations of assembled poses q for the drives' rates `dv` and
  !> accelerations `da` (rad/s, rad/s^2 or m/s, m/s^2), with J's factors from `work` (of
  !> linkage_assemble) when they are those of q.
  pure subroutine linkage_motion(mech, q, dv, da, qd, qdd, work, error)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses.
    real(wp), intent(in) :: q(:)
    !> Drive rates and accelerations.
    real(wp), intent(in) :: dv(:), da(:)
    !> Velocities and accelerations of the poses.
    real(wp), intent(out) :: qd(:), qdd(:)
    !> Workspace (J and its factors at the last poses).
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    integer :: d
    logical :: ok
    qd = 0.0_wp
    qdd = 0.0_wp
    call work_ready(mech, work)
    if (use_fast(work)) then
      ! from the points: qd from the velocity analogues, qdd unit by unit
      call fast_analogues(mech, q, work, ok)
      if (ok) then
        do d = 1, size(mech%drives)
          qd = qd + work%v(1:size(q), d) * dv(d)
        end do
        call work_turns(work, q)
        call dyad_accelerations(mech, work%plan, q, work%cs, qd, da, qdd)
        return
      end if
    end if
    call work_factored(mech, q, work, error)
    if (allocated(error)) return
    qd = 0.0_wp
    do d = 1, size(mech%drives)
      qd(drive_row(mech, d)) = dv(d)
    end do
    call solve_j(mech, work, qd, work%rhs, work%unit_x)
    call work_turns(work, q)
    call quadratic_terms(mech, q, qd, work%zero_q, qdd, work%cs)
    qdd = -qdd
    do d = 1, size(mech%drives)
      qdd(drive_row(mech, d)) = qdd(drive_row(mech, d)) + da(d)
    end do
    call solve_j(mech, work, qdd, work%rhs, work%unit_x)
  end subroutine linkage_motion

  !> Reactions of an assembled, moving step: applied forces `fval` (N, along each force's
  !> direction) and moments `mval` (N*m), gravity and inertia, and the self-check: the
  !> equilibrium of every link with the physical forces, the power balance of every drive
  !> with the velocity analogues. Every unit an input unit of one link or a dyad (the fast
  !> path, whose velocity analogues linkage_assemble or linkage_motion found at these poses):
  !> by the group method's free bodies in closed form, unit by unit (linkage_free_body), and
  !> at the first step solved with `work` also by the Lagrange multipliers (J^T lambda = -Q)
  !> as the second opinion (step%solver_gap; 0 at the other steps). Otherwise: by the Lagrange
  !> multipliers, with the group method as the second opinion where a unit was factored by
  !> LU (step%solver_gap).
  pure subroutine linkage_statics(mech, fval, mval, step, work, error, moved)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Force magnitudes (N) and moments (N*m) of the step.
    real(wp), intent(in) :: fval(:), mval(:)
    !> In: q, qd, qdd; out: forces, efforts and the self-check.
    type(linkage_step_t), intent(inout) :: step
    !> Workspace (J and its factors at the last poses).
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    !> True: linkage_fast_motion solved step%q with `work` just before (its velocity
    !> analogues and turns are those of step%q).
    logical, intent(in), optional :: moved
    real(wp) :: terms, power, s(2), vs(2), as(2), ref(2), f_length, fk(2)
    integer :: n, k, d, i
    logical :: closed, fast, known
    n = size(mech%links)
    call work_ready(mech, work)
    known = .false.
    if (present(moved)) known = moved
    fast = use_fast(work) .and. work%has_fast
    if (fast .and. .not. known) fast = same_poses(work%q_fast, step%q)
    if (.not. fast) then
      call work_factored(mech, step%q, work, error)
      if (allocated(error)) return
    end if
    if (.not. (fast .and. known)) call work_turns(work, step%q)
    call generalised_loads(mech, step%q, step%qd, step%qdd, fval, mval, work%gen, work%cs, work%s_cm, work%a_cm)

    ! (a step reused from the step before keeps its arrays)
    if (allocated(step%f)) then
      if (size(step%f, 2) /= size(mech%pairs) .or. size(step%effort) /= size(mech%drives)) then
        deallocate (step%f, step%normal, step%couple, step%effort)
      end if
    end if
    if (.not. allocated(step%f)) then
      allocate (step%f(2, size(mech%pairs)), step%normal(size(mech%pairs)), step%couple(size(mech%pairs)))
      allocate (step%effort(size(mech%drives)))
    end if

    step%solver_gap = 0.0_wp
    if (fast) then
      ! each link's own loads (force, moment about its reference point: Q), then the units'
      ! reactions in closed form, the last first (kinetostat_linkage_dyads)
      do i = 1, n
        work%load(:, i) = work%gen(3 * i - 2:3 * i)
      end do
      call dyad_reactions(mech, work%plan, step%q, work%cs, work%load, step%f, step%normal, step%couple, step%effort, &
                          closed)
      if (.not. closed) then
        ! (a 2 x 2 near a zero determinant: the free bodies by LU decide)
        call free_bodies(mech, fval, mval, step%q, step%qd, step%qdd, work, step%f, step%normal, step%couple, &
                         step%effort, error)
        if (allocated(error)) return
      end if
      work%fast_statics = work%fast_statics + 1
      if (work%fast_statics == 1) then
        ! the second opinion at the workspace's first step: the Lagrange multipliers
        call work_factored(mech, step%q, work, error)
        if (allocated(error)) return
        call lagrange_reactions(mech, work, work%f2, work%normal2, work%couple2, work%effort2, error)
        if (allocated(error)) return
        step%solver_gap = linkage_reaction_gap(mech, step, work%f2, work%normal2, work%couple2, work%effort2)
        ! (work_factored put J's velocity analogues into work%v: the power balance below
        ! takes those of the points, as at every other step)
        work%has_fast = .false.
        call fast_analogues(mech, step%q, work, fast)
      end if
    else
      call lagrange_reactions(mech, work, step%f, step%normal, step%couple, step%effort, error)
      if (allocated(error)) return
      ! the second opinion: the course's group method, which shares no equation with the
      ! above, where a unit was solved by LU (a class-III or class-IV group, a dyad near a
      ! zero determinant, the general solve); every unit in closed form: the equilibrium of
      ! every link below (the group method's equations with these reactions) is the check
      closed = by_rows(work)
      if (closed) closed = all(work%unit_small)
      if (.not. closed) then
        call free_bodies(mech, fval, mval, step%q, step%qd, step%qdd, work, work%f2, work%normal2, work%couple2, &
                         work%effort2, error)
        if (allocated(error)) return
        step%solver_gap = linkage_reaction_gap(mech, step, work%f2, work%normal2, work%couple2, work%effort2)
      end if
    end if

    ! self-check 1: every link's equilibrium with the physical forces at their points (the
    ! centres of mass and their accelerations of generalised_loads; the fast path's reactions
    ! kept the turns of step%q)
    if (.not. fast) call work_turns(work, step%q)
    work%bal(:) = link_balance_t()
    do i = 1, n
      ref = step%q(3 * i - 2:3 * i - 1)
      associate (lk => mech%links(i))
        s = work%s_cm(:, i)
        as = work%a_cm(:, i)
        call balance_add_force(work%bal(i), ref, s, lk%m * mech%gravity)
        call balance_add_force(work%bal(i), ref, s, -lk%m * as)
        call balance_add_couple(work%bal(i), -lk%j * step%qdd(3 * i))
      end associate
    end do
    do k = 1, size(mech%forces)
      associate (fc => mech%forces(k))
        s = position_cs(mech, step%q, work%cs, fc%link, fc%at)
        call balance_add_force(work%bal(fc%link), step%q(3 * fc%link - 2:3 * fc%link - 1), s, fval(k) * force_dir(fc))
      end associate
    end do
    do k = 1, size(mech%moment_link)
      call balance_add_couple(work%bal(mech%moment_link(k)), mval(k))
    end do
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        ! (the force's length once for both links: |f| = |-f|; fk: a copy of fixed size, so
        ! that -fk takes no temporary array from the heap)
        fk = step%f(:, k)
        f_length = fast_magnitude(fk)
        if (pr%kind == pair_r) then
          ! each link's own coordinates of the joint (they differ by Newton's residual, whose
          ! lever would otherwise show in the moments of a link whose loads all act there)
          if (fast) then
            ! (the points the fast path took at these poses)
            s = work%plan%xa(:, k)
            vs = work%plan%xb(:, k)
          else
            s = position_cs(mech, step%q, work%cs, pr%a, pr%at)
            vs = position_cs(mech, step%q, work%cs, pr%b, pr%at)
          end if
          call balance_on(work%bal, step%q, pr%a, s, fk, 0.0_wp, f_length)
          call balance_on(work%bal, step%q, pr%b, vs, -fk, 0.0_wp, f_length)
        else
          if (fast) then
            s = work%plan%xa(:, k)
          else
            s = position_cs(mech, step%q, work%cs, pr%a + pr%b - pr%guide, pr%at)
          end if
          call balance_on(work%bal, step%q, pr%a, s, fk, step%couple(k), f_length)
          call balance_on(work%bal, step%q, pr%b, s, -fk, -step%couple(k), f_length)
        end if
      end associate
    end do
    do d = 1, size(mech%drives)
      associate (pr => mech%pairs(mech%drives(d)%pair))
        if (pr%kind == pair_r) then
          ! (a couple only)
          if (pr%a > 0 .and. step%effort(d) /= 0.0_wp) call balance_add_couple(work%bal(pr%a), step%effort(d))
          if (pr%b > 0 .and. step%effort(d) /= 0.0_wp) call balance_add_couple(work%bal(pr%b), -step%effort(d))
        else
          s = position_cs(mech, step%q, work%cs, pr%a + pr%b - pr%guide, pr%at)
          vs = turned(work%cs, pr%guide, pr%u) * step%effort(d)
          f_length = fast_magnitude(vs)
          call balance_on(work%bal, step%q, pr%a, s, vs, 0.0_wp, f_length)
          call balance_on(work%bal, step%q, pr%b, s, -vs, 0.0_wp, f_length)
        end if
      end associate
    end do
    step%residual = equilibrium_residual(work%bal)

    ! self-check 2: each drive's effort by virtual work (the velocity analogue of that drive)
    step%mismatch = 0.0_wp
    do d = 1, size(mech%drives)
      power = 0.0_wp
      terms = 0.0_wp
      do i = 1, size(work%gen)
        power = power - work%gen(i) * work%v(i, d)
        terms = terms + abs(work%gen(i) * work%v(i, d))
      end do
      associate (pr => mech%pairs(mech%drives(d)%pair))
        ! the effort acts on link a; for a stroke whose guide is on a, the stroke grows as a
        ! moves against u
        if (pr%kind == pair_p .and. pr%guide == pr%a) power = -power
      end associate
      step%mismatch = max(step%mismatch, power_mismatch(step%effort(d), power, terms))
    end do
  contains
    !> Direction of force fc in the step's pose.
    pure function force_dir(fc) result(w)
      type(linkage_force_t), intent(in) :: fc
      real(wp) :: w(2)
      w = fc%dir
      if (fc%follow) w = turned(work%cs, fc%link, fc%dir)
    end function force_dir
  end subroutine linkage_statics

  !> Adds force f (N; f_len: its fast_magnitude) at point p (m) and couple c (N*m) to link
  !> i's balance, its moments about the link's reference point of poses q (nothing for the
  !> frame; a zero force or couple is not added).
  pure subroutine balance_on(bal, q, i, p, f, c, f_len)
    type(link_balance_t), intent(inout) :: bal(:)
    real(wp), intent(in) :: q(:), p(2), f(2), c, f_len
    integer, intent(in) :: i
    real(wp) :: origin(2)
    if (i == 0) return
    if (f(1) /= 0.0_wp .or. f(2) /= 0.0_wp) then
      ! (a copy of fixed size: no packing of the section of an assumed-shape q)
      origin(1) = q(3 * i - 2)
      origin(2) = q(3 * i - 1)
      call balance_add_force(bal(i), origin, p, f, f_len)
    end if
    if (c /= 0.0_wp) call balance_add_couple(bal(i), c)
  end subroutine balance_on

  !> The reactions by the Lagrange multipliers of the constraints, J^T lambda = -Q (Q: the
  !> generalised loads in work%gen; J's factors in work at the step's poses, whose turns
  !> work%cs holds), as linkage_step_t's f, normal, couple, effort.
  pure subroutine lagrange_reactions(mech, work, f, normal, couple, effort, error)
    type(linkage_t), intent(in) :: mech
    type(linkage_work_t), intent(inout) :: work
    real(wp), intent(out) :: f(:, :), normal(:), couple(:), effort(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: s(2)
    integer :: k, d, r
    work%lam(:) = -work%gen
    if (work%blocked) then
      ! J^T is block triangular too: its units' blocks are J's, transposed
      call solve_jt(mech, work, work%lam, work%rhs, work%unit_x)
    else
      work%jt(:, :) = transpose(work%jac)
      call factor_dense(work%jt, work%lut, work%ipivt, error, work%trsm)
      if (allocated(error)) return
      call solve_factored(work%lut, work%ipivt, work%lam)
    end if
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        r = pair_row(k)
        if (pr%kind == pair_r) then
          f(:, k) = work%lam(r:r + 1)
          normal(k) = 0.0_wp
          couple(k) = 0.0_wp
        else
          ! rows: couple lambda(r) and normal force lambda(r+1)*n on the block
          s = perp(turned(work%cs, pr%guide, pr%u))
          if (pr%guide == pr%b) then
            normal(k) = work%lam(r + 1)
            couple(k) = work%lam(r)
          else
            normal(k) = -work%lam(r + 1)
            couple(k) = -work%lam(r)
          end if
          f(:, k) = normal(k) * s
        end if
      end associate
    end do
    do d = 1, size(mech%drives)
      associate (pr => mech%pairs(mech%drives(d)%pair))
        effort(d) = work%lam(drive_row(mech, d))
        if (pr%kind == pair_p .and. pr%guide == pr%a) effort(d) = -effort(d)
      end associate
    end do
  end subroutine lagrange_reactions

  !> The reactions by the course's group method, independently of the Lagrange form: every
  !> link a free body (its own loads: gravity, d'Alembert's force -m a_S and moment -J_S eps,
  !> the external forces and moments; the pair forces at the joints), three equations per
  !> link (the forces' sum, the moments about its centre of mass), the units of the
  !> structural analysis solved one by one from the last group to the input units, each with
  !> the forces of the groups solved before it. The unknowns of a unit: the force of each of
  !> its turning pairs (on link a from b, 2 components), the normal force and couple of each
  !> sliding pair (on a: the force along the guide's normal at the block's point), the effort
  !> of each drive (on a). Results as linkage_step_t's f, normal, couple, effort.
  pure subroutine linkage_free_body(mech, fval, mval, step, work, f, normal, couple, effort, error)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Force magnitudes (N) and moments (N*m) of the step.
    real(wp), intent(in) :: fval(:), mval(:)
    !> The step's poses q, velocities qd and accelerations qdd.
    type(linkage_step_t), intent(in) :: step
    !> Workspace.
    type(linkage_work_t), intent(inout) :: work
    !> Force on link a from b of every pair, N (2 x pairs).
    real(wp), intent(out) :: f(:, :)
    !> Sliding pairs: the normal force on a (N) and the couple on a (N*m); 0 for turning pairs.
    real(wp), intent(out) :: normal(:), couple(:)
    !> Effort of every drive on link a: moment (N*m) or force along the guide (N).
    real(wp), intent(out) :: effort(:)
    type(error_t), allocatable, intent(out) :: error
    call free_bodies(mech, fval, mval, step%q, step%qd, step%qdd, work, f, normal, couple, effort, error)
  end subroutine linkage_free_body

  !> linkage_free_body of poses q, velocities qd and accelerations qdd.
  pure subroutine free_bodies(mech, fval, mval, q, qd, qdd, work, f, normal, couple, effort, error)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: fval(:), mval(:)
    real(wp), intent(in) :: q(:), qd(:), qdd(:)
    type(linkage_work_t), intent(inout) :: work
    real(wp), intent(out) :: f(:, :)
    real(wp), intent(out) :: normal(:), couple(:)
    real(wp), intent(out) :: effort(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: sv(2), vs(2), as(2), w(2), g(2, 2), h(2), pa(2), pb(2)
    integer :: i, j, k, d, c, r, u, nu, np
    logical :: solved
    f = 0.0_wp
    normal = 0.0_wp
    couple = 0.0_wp
    effort = 0.0_wp
    call work_ready(mech, work)
    call work_turns(work, q)
    np = size(mech%pairs)
    ! each link's own loads: the force and its moment about the centre of mass
    do i = 1, size(mech%links)
      associate (lk => mech%links(i))
        call link_point_state(mech, q, qd, qdd, i, lk%s, sv, vs, as, work%cs)
        work%cm(:, i) = sv
        work%load(1:2, i) = lk%m * mech%gravity - lk%m * as
        work%load(3, i) = -lk%j * qdd(3 * i)
      end associate
    end do
    do k = 1, size(mech%forces)
      associate (fc => mech%forces(k))
        w = fc%dir
        if (fc%follow) w = turned(work%cs, fc%link, fc%dir)
        w = fval(k) * w
        pa = position_cs(mech, q, work%cs, fc%link, fc%at)
        work%load(1:2, fc%link) = work%load(1:2, fc%link) + w
        work%load(3, fc%link) = work%load(3, fc%link) + cross(pa - work%cm(:, fc%link), w)
      end associate
    end do
    do k = 1, size(mech%moment_link)
      work%load(3, mech%moment_link(k)) = work%load(3, mech%moment_link(k)) + mval(k)
    end do
    work%pair_known(:) = .false.
    work%drive_known(:) = .false.
    work%local(:) = 0
    do u = size(mech%units), 1, -1
      associate (unit => mech%units(u))
        nu = size(unit%rows)
        do j = 1, size(unit%links)
          work%local(unit%links(j)) = j
          work%fb(3 * j - 2:3 * j) = -work%load(:, unit%links(j))
        end do
        work%fa(1:nu, 1:nu) = 0.0_wp
        ! the forces known from the groups solved before: each pair's force f on a (for a
        ! sliding pair the normal force times the guide's normal, at the block's point) and
        ! its reaction on b, with a sliding pair's couple
        do k = 1, np
          if (.not. work%pair_known(k)) cycle
          call pair_effect(work%cs, k, g, h, pa, pb)
          call add_known(work, mech%pairs(k)%a, pa, f(:, k), 0.0_wp)
          call add_known(work, mech%pairs(k)%b, pb, -f(:, k), 0.0_wp)
          if (mech%pairs(k)%kind == pair_p) then
            call add_known(work, mech%pairs(k)%a, pa, [0.0_wp, 0.0_wp], couple(k))
            call add_known(work, mech%pairs(k)%b, pb, [0.0_wp, 0.0_wp], -couple(k))
          end if
        end do
        do d = 1, size(mech%drives)
          if (.not. work%drive_known(d)) cycle
          call drive_effect(work%cs, d, w, h(1), pa)
          call add_known(work, mech%pairs(mech%drives(d)%pair)%a, pa, w * effort(d), h(1) * effort(d))
          call add_known(work, mech%pairs(mech%drives(d)%pair)%b, pa, -w * effort(d), -h(1) * effort(d))
        end do
        ! the unit's unknowns: a column per constraint row of the unit
        do c = 1, nu
          r = unit%rows(c)
          if (r <= 2 * np) then
            if (mod(r, 2) == 0) cycle
            k = (r + 1) / 2
            call pair_effect(work%cs, k, g, h, pa, pb)
            call add_column(work, c, mech%pairs(k)%a, pa, g(:, 1), h(1))
            call add_column(work, c, mech%pairs(k)%b, pb, -g(:, 1), -h(1))
            call add_column(work, c + 1, mech%pairs(k)%a, pa, g(:, 2), h(2))
            call add_column(work, c + 1, mech%pairs(k)%b, pb, -g(:, 2), -h(2))
          else
            d = r - 2 * np
            call drive_effect(work%cs, d, w, h(1), pa)
            call add_column(work, c, mech%pairs(mech%drives(d)%pair)%a, pa, w, h(1))
            call add_column(work, c, mech%pairs(mech%drives(d)%pair)%b, pa, -w, -h(1))
          end if
        end do
        ! an input unit of one link and a dyad in closed form (kinetostat_linkage_small),
        ! any other unit, or one whose closed form is near a zero determinant, densely
        ! (the unknowns' columns are the unit's rows: a dyad's places as dyad_rows finds them)
        solved = .false.
        if (work%small_solves .and. work%blocked) then
          if (nu == 3 .and. size(unit%links) == 1) then
            call solve3(work%fa(1:3, 1:3), work%fb(1:3), work%unit_x(1:3), solved)
          else if (nu == 6 .and. work%unit_dyad(1, u) > 0) then
            call two_body_solve(work%fa(1:6, 1:6), work%fb(1:6), work%unit_dyad(1, u), work%unit_dyad(2, u), &
                                work%unit_dyad(3, u), work%unit_x(1:6), solved)
          end if
        end if
        if (solved) then
          work%fb(1:nu) = work%unit_x(1:nu)
        else
          call factor_dense(work%fa(1:nu, 1:nu), work%flu(1:nu, 1:nu), work%fipiv(1:nu), error)
          if (allocated(error)) return
          call solve_factored(work%flu(1:nu, 1:nu), work%fipiv(1:nu), work%fb(1:nu))
        end if
        do c = 1, nu
          r = unit%rows(c)
          if (r <= 2 * np) then
            if (mod(r, 2) == 0) cycle
            k = (r + 1) / 2
            if (mech%pairs(k)%kind == pair_r) then
              f(:, k) = work%fb(c:c + 1)
            else
              ! column c: the couple, c + 1: the normal force
              call pair_effect(work%cs, k, g, h, pa, pb)
              couple(k) = work%fb(c)
              normal(k) = work%fb(c + 1)
              f(:, k) = normal(k) * g(:, 2)
            end if
            work%pair_known(k) = .true.
          else
            d = r - 2 * np
            effort(d) = work%fb(c)
            work%drive_known(d) = .true.
          end if
        end do
        do j = 1, size(unit%links)
          work%local(unit%links(j)) = 0
        end do
      end associate
    end do
  contains
    !> A pair's two unknowns as loads on link a: the forces g(:, 1), g(:, 2) and couples h(1),
    !> h(2) per unit of each; their points on a (pa) and on b (pb). Turning pair: the force's
    !> components at the joint of each link. Sliding pair: the couple, then the normal force
    !> at the block's point (for R and P alike: a force in a column times its unknown).
    pure subroutine pair_effect(cs, k, g, h, pa, pb)
      real(wp), intent(in) :: cs(:, 0:)
      integer, intent(in) :: k
      real(wp), intent(out) :: g(2, 2), h(2), pa(2), pb(2)
      associate (pr => mech%pairs(k))
        if (pr%kind == pair_r) then
          g(:, 1) = [1.0_wp, 0.0_wp]
          g(:, 2) = [0.0_wp, 1.0_wp]
          h = 0.0_wp
          pa = position_cs(mech, q, cs, pr%a, pr%at)
          pb = position_cs(mech, q, cs, pr%b, pr%at)
        else
          g(:, 1) = 0.0_wp
          g(:, 2) = perp(turned(cs, pr%guide, pr%u))
          h = [1.0_wp, 0.0_wp]
          pa = position_cs(mech, q, cs, pr%a + pr%b - pr%guide, pr%at)
          pb = pa
        end if
      end associate
    end subroutine pair_effect
    !> A drive's effort as a load on link a per unit: the force w at point p and the couple h.
    pure subroutine drive_effect(cs, d, w, h, p)
      real(wp), intent(in) :: cs(:, 0:)
      integer, intent(in) :: d
      real(wp), intent(out) :: w(2), h, p(2)
      associate (pr => mech%pairs(mech%drives(d)%pair))
        if (pr%kind == pair_r) then
          w = 0.0_wp
          h = 1.0_wp
          p = 0.0_wp
        else
          w = turned(cs, pr%guide, pr%u)
          h = 0.0_wp
          p = position_cs(mech, q, cs, pr%a + pr%b - pr%guide, pr%at)
        end if
      end associate
    end subroutine drive_effect
    !> Force fo at point p and couple co on link i (if it is in the unit): column c of the
    !> unit's system.
    pure subroutine add_column(work, c, i, p, fo, co)
      type(linkage_work_t), intent(inout) :: work
      integer, intent(in) :: c, i
      real(wp), intent(in) :: p(2), fo(2), co
      integer :: e
      if (i == 0) return
      e = work%local(i)
      if (e == 0) return
      work%fa(3 * e - 2, c) = work%fa(3 * e - 2, c) + fo(1)
      work%fa(3 * e - 1, c) = work%fa(3 * e - 1, c) + fo(2)
      work%fa(3 * e, c) = work%fa(3 * e, c) + cross(p - work%cm(:, i), fo) + co
    end subroutine add_column
    !> A known force fo at point p and couple co on link i (if it is in the unit): to the
    !> right-hand side.
    pure subroutine add_known(work, i, p, fo, co)
      type(linkage_work_t), intent(inout) :: work
      integer, intent(in) :: i
      real(wp), intent(in) :: p(2), fo(2), co
      integer :: e
      if (i == 0) return
      e = work%local(i)
      if (e == 0) return
      work%fb(3 * e - 2) = work%fb(3 * e - 2) - fo(1)
      work%fb(3 * e - 1) = work%fb(3 * e - 1) - fo(2)
      work%fb(3 * e) = work%fb(3 * e) - cross(p - work%cm(:, i), fo) - co
    end subroutine add_known
  end subroutine free_bodies

  !> Largest difference of two sets of reactions (the step's and another's: f, normal,
  !> couple, effort), relative to the step's largest reaction (force components of the
  !> turning pairs, normal forces and couples of the sliding pairs, efforts).
  pure real(wp) function linkage_reaction_gap(mech, step, f, normal, couple, effort) result(gap)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> The step's reactions.
    type(linkage_step_t), intent(in) :: step
    !> The other reactions.
    real(wp), intent(in) :: f(:, :), normal(:), couple(:), effort(:)
    real(wp) :: big, diff
    integer :: k
    big = 0.0_wp
    diff = 0.0_wp
    do k = 1, size(mech%pairs)
      if (mech%pairs(k)%kind == pair_r) then
        big = max(big, abs(step%f(1, k)), abs(step%f(2, k)))
        diff = max(diff, abs(step%f(1, k) - f(1, k)), abs(step%f(2, k) - f(2, k)))
      else
        big = max(big, abs(step%normal(k)), abs(step%couple(k)))
        diff = max(diff, abs(step%normal(k) - normal(k)), abs(step%couple(k) - couple(k)))
      end if
    end do
    do k = 1, size(mech%drives)
      big = max(big, abs(step%effort(k)))
      diff = max(diff, abs(step%effort(k) - effort(k)))
    end do
    gap = 0.0_wp
    if (big > 0.0_wp) gap = diff / big
  end function linkage_reaction_gap

  !> Generalised applied loads Q (3 per link: force, moment about the reference point):
  !> external forces and moments, gravity, d'Alembert's inertia force and moment.
  pure subroutine generalised_loads(mech, q, qd, qdd, fval, mval, gen, cs, s_cm, a_cm)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), qd(:), qdd(:), fval(:), mval(:)
    !> Q (3n).
    real(wp), intent(out) :: gen(:)
    !> The turns of q (set_turns).
    real(wp), intent(in) :: cs(:, 0:)
    !> Each link's centre of mass (m) and its acceleration (m/s^2), 2 x n.
    real(wp), intent(out) :: s_cm(:, :), a_cm(:, :)
    real(wp) :: s(2), as(2), f(2), w(2), r(2)
    integer :: i, k
    gen = 0.0_wp
    do i = 1, size(mech%links)
      associate (lk => mech%links(i))
        ! (link_point_state's arithmetic: the centre of mass from the reference point, r)
        r = turned(cs, i, lk%s - lk%c)
        s = q(3 * i - 2:3 * i - 1) + r
        as = qdd(3 * i - 2:3 * i - 1) + qdd(3 * i) * perp(r) - qd(3 * i)**2 * r
        s_cm(:, i) = s
        a_cm(:, i) = as
        f = lk%m * (mech%gravity - as)
        call add_gen(gen, i, s, f)
        gen(3 * i) = gen(3 * i) - lk%j * qdd(3 * i)
      end associate
    end do
    do k = 1, size(mech%forces)
      associate (fc => mech%forces(k))
        w = fc%dir
        if (fc%follow) w = turned(cs, fc%link, fc%dir)
        call add_gen(gen, fc%link, position_cs(mech, q, cs, fc%link, fc%at), fval(k) * w)
      end associate
    end do
    do k = 1, size(mech%moment_link)
      gen(3 * mech%moment_link(k)) = gen(3 * mech%moment_link(k)) + mval(k)
    end do
  contains
    pure subroutine add_gen(gen, i, p, f)
      real(wp), intent(inout) :: gen(:)
      integer, intent(in) :: i
      real(wp), intent(in) :: p(2), f(2)
      gen(3 * i - 2:3 * i - 1) = gen(3 * i - 2:3 * i - 1) + f
      gen(3 * i) = gen(3 * i) + cross(p - q(3 * i - 2:3 * i - 1), f)
    end subroutine add_gen
  end subroutine generalised_loads

end module kinetostat_linkage
