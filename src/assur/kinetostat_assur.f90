!> Generic mechanism, layer 3: assembly of a one-DOF planar linkage = frame + initial link
!> (crank) + an ordered list of class-II dyads, and its kinetostatics at one input angle:
!> kinematics link by link, gravity and d'Alembert loads of every link (manual section 5:
!> reduced to the link's frame origin), reactions dyad by dyad from the last back to the
!> first (a solved dyad's reactions become loads on the links it hangs on), then the crank's
!> pin reaction and balancing moment; self-check by per-link equilibrium residuals and the
!> power (virtual work) balance of the balancing moment.
!>
!> Internal link indices: 0 frame, 1 crank, dyad d owns links 2d (a) and 2d+1 (b).
!> Pair index of the results: 3(d-1)+j for pair j of dyad d; the crank's pin is 3*nd+1.
!> Alternatively a linear actuator (a prismatic pair of a dyad) drives: its axial force is
!> the unknown instead of the crank's balancing moment (drive_by_actuator).
module kinetostat_assur
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_vec2, only: unit_at, cross, magnitude, fast_magnitude
  use kinetostat_loads, only: inertia_force, inertia_moment, gravity_force
  use kinetostat_selfcheck, only: link_balance_t, balance_add_force, balance_add_couple, &
    equilibrium_residual, power_mismatch, balance_add_balance, load_moment_scale
  use kinetostat_text, only: int_str
  use kinetostat_format, only: trimmed_es
  use kinetostat_assur_kinematics, only: link_state_t, point_state_t, dyad_geometry_t, dyad_pose_t, &
    set_crank_state, point_motion, set_dyad_pose, kind_names, pose_ok, pose_no_assembly, kind_rrp, &
    kind_prp, kind_rpp
  use kinetostat_assur_statics, only: dyad_reactions_t, dyad_reactions, pair_is_prismatic
  implicit none
  private
  public :: assur_link_t, assur_dyad_t, assur_force_t, assur_mech_t, assur_step_t
  public :: assur_step, assur_kinematics, link_a, link_b, pair_index, crank_pin_index, pair_sides
  public :: output_pair_of, output_position, link_position, assur_extreme

  !> An actuator whose crank moment per newton |stroke'| is below this times the driving
  !> dyad's size (m) is in a dead position: it cannot move the input link.
  real(wp), parameter :: drive_dead_rel = 1.0e-9_wp

  !> Mass data of a moving link.
  type :: assur_link_t
    !> Number of the link in the deck (for column names), >= 0.
    integer :: id = 0
    !> Mass, kg.
    real(wp) :: m = 0.0_wp
    !> Moment of inertia about the centre of mass, kg*m^2.
    real(wp) :: j = 0.0_wp
    !> Centre of mass in the link's coordinates, m.
    real(wp) :: s(2) = 0.0_wp
  end type assur_link_t

  !> A dyad and where it hangs.
  type :: assur_dyad_t
    !> Kind, assembly mode and dimensions.
    type(dyad_geometry_t) :: geom
    !> Internal indices of the links its outer pairs 1 and 3 attach to (< its own links).
    integer :: on(2) = 0
    !> Attachment points in those links' coordinates (pin or a point of the guide), m.
    real(wp) :: at(2, 2) = 0.0_wp
    !> Guide directions relative to those links (prismatic outer pairs), rad.
    real(wp) :: ang(2) = 0.0_wp
  end type assur_dyad_t

  !> An external force on a link (its magnitude is given per step).
  type :: assur_force_t
    !> Internal index of the loaded link (>= 1).
    integer :: link = 1
    !> Point of application in the link's coordinates, m.
    real(wp) :: at(2) = 0.0_wp
    !> Direction, rad: global, or relative to the link's x-axis when `follow`.
    real(wp) :: angle = 0.0_wp
    !> Whether the direction turns with the link.
    logical :: follow = .false.
  end type assur_force_t

  !> A validated mechanism.
  type :: assur_mech_t
    !> Crank pivot A on the frame, global, m.
    real(wp) :: pivot(2) = 0.0_wp
    !> Gravity, m/s^2.
    real(wp) :: g = 0.0_wp
    !> Unit vector of gravity's direction, global.
    real(wp) :: down(2) = [0.0_wp, -1.0_wp]
    !> Frame (index 0), crank (1) and the dyads' links (2 .. 2*nd+1).
    type(assur_link_t), allocatable :: links(:)
    !> The dyads in attachment order.
    type(assur_dyad_t), allocatable :: dyads(:)
    !> External forces.
    type(assur_force_t), allocatable :: forces(:)
    !> Internal index of the link each external moment acts on.
    integer, allocatable :: moment_link(:)
    !> Dyad whose prismatic pair is the driving linear actuator (0: the crank's balancing
    !> moment drives).
    integer :: drive_dyad = 0
    !> The actuator's pair in that dyad (1 outer of a, 2 inner, 3 outer of b).
    integer :: drive_pair = 0
    !> Internal index of the output link (extreme positions, load tables over its position).
    integer :: output_link = 1
    !> 0: the output position is the link's angle; j: it slides on a frame guide and its
    !> position is the stroke of pair j of its dyad.
    integer :: output_pair = 0
  end type assur_mech_t

  !> Results at one input angle (forces global, N; moments N*m).
  type :: assur_step_t
    !> Crank angle, rad.
    real(wp) :: phi1 = 0.0_wp
    !> Crank speed, rad/s.
    real(wp) :: omega1 = 0.0_wp
    !> Crank angular acceleration, rad/s^2.
    real(wp) :: eps1 = 0.0_wp
    !> Pair forces (2, 3*nd+1): dyad pairs then the crank pin (on the crank from the frame), N.
    real(wp), allocatable :: f(:, :)
    !> Signed normal force of prismatic pairs (0 for revolute), N.
    real(wp), allocatable :: n(:)
    !> Reaction moment of prismatic pairs about their reference points (0 for revolute), N*m.
    real(wp), allocatable :: m(:)
    !> Balancing moment on the crank, N*m, CCW positive.
    real(wp) :: m1 = 0.0_wp
    !> The same from the power balance (virtual work), N*m.
    real(wp) :: m1_power = 0.0_wp
    !> Largest relative equilibrium residual of the moving links.
    real(wp) :: residual = 0.0_wp
    !> Relative mismatch |M1 - M1_power| / scale (|F_drive - F_drive_power| with an actuator).
    real(wp) :: mismatch = 0.0_wp
    !> Scale of the power balance: sum of the magnitudes of its terms (per unit crank speed), N*m.
    real(wp) :: power_scale = 0.0_wp
    !> Size of the driving effort the step's applied loads make (weights, inertia, external
    !> and friction loads): N*m for the crank (load_moment_scale with the mechanism's size),
    !> N for an actuator (the largest force sum of a link). Never 0 while a load acts,
    !> unlike `power_scale` (a load doing no work).
    real(wp) :: load_scale = 0.0_wp
    !> Actuator (driving prismatic pair) only: axial force, N, positive extending it.
    real(wp) :: f_drive = 0.0_wp
    !> The same from the power balance, N.
    real(wp) :: f_drive_power = 0.0_wp
    !> Actuator stroke (sliding side's position along the pair relative to the other side), m.
    real(wp) :: stroke = 0.0_wp
    !> Stroke speed, m/s.
    real(wp) :: stroke_v = 0.0_wp
    !> Stroke acceleration, m/s^2.
    real(wp) :: stroke_a = 0.0_wp
    !> Whether a step solved into this result computes the links' angles (work_states%th;
    !> false: where no dyad after a link turns a guide with it, the angles of the RRR and
    !> RRP links are NaN and take no atan2 -- for a caller that shows no link angle).
    logical :: link_angles = .true.
    !> Workspace kept between the steps a caller solves into this result (no heap per
    !> step): the links' frames (0..2*nd+1), the dyads' poses (nd) and the links' loads
    !> (0..2*nd+1).
    type(link_state_t), allocatable :: work_states(:)
    !> See work_states.
    type(dyad_pose_t), allocatable :: work_poses(:)
    !> See work_states.
    type(link_balance_t), allocatable :: work_known(:)
    !> See work_states: every pair force's length as the self-check takes it (3*nd+1), N.
    real(wp), allocatable :: work_f_len(:)
    !> See work_states: each external force's angle (rad, mech%forces(k)%angle) and its
    !> [cos, sin], taken again only when the angle is another.
    real(wp), allocatable :: work_force_angle(:)
    !> See work_force_angle.
    real(wp), allocatable :: work_force_dir(:, :)
  end type assur_step_t

contains

  !> Internal index of link a (first link) of dyad `d`.
  elemental integer function link_a(d)
    !> Dyad number.
    integer, intent(in) :: d
    link_a = 2 * d
  end function link_a

  !> Internal index of link b (second link) of dyad `d`.
  elemental integer function link_b(d)
    !> Dyad number.
    integer, intent(in) :: d
    link_b = 2 * d + 1
  end function link_b

  !> Result index of pair `j` (1..3) of dyad `d`.
  elemental integer function pair_index(d, j)
    !> Dyad number.
    integer, intent(in) :: d
    !> Pair: 1 outer of a, 2 inner, 3 outer of b.
    integer, intent(in) :: j
    pair_index = 3 * (d - 1) + j
  end function pair_index

  !> Result index of the crank's pin when there are `nd` dyads.
  elemental integer function crank_pin_index(nd)
    !> Number of dyads.
    integer, intent(in) :: nd
    crank_pin_index = 3 * nd + 1
  end function crank_pin_index

  !> "dyad d (KIND, links i-j)" for messages.
  pure function dyad_label(mech, d) result(s)
    type(assur_mech_t), intent(in) :: mech
    integer, intent(in) :: d
    character(len=:), allocatable :: s
    s = "dyad "//int_str(d)//" ("//kind_names(mech%dyads(d)%geom%kind)//", links "// &
        int_str(mech%links(link_a(d))%id)//"-"//int_str(mech%links(link_b(d))%id)//")"
  end function dyad_label

  !> Kinematics of every link at crank angle `phi1` (rad): frames 0..2*nd+1 and dyad poses.
  pure subroutine assur_kinematics(mech, phi1, states, poses, error, link_angles)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Frames of links 0..2*nd+1 (each one set here, up to the failing dyad's on an error;
    !> inout only to spare every step a second initialisation of them; explicit shapes: a
    !> step's arrays are contiguous, and the strides of assumed shapes cost a small
    !> mechanism's step more than its sums).
    type(link_state_t), intent(inout) :: states(0:2 * size(mech%dyads) + 1)
    !> Pose of each dyad (each one set here, up to the failing one on an error; inout only to
    !> spare every step a second initialisation of them).
    type(dyad_pose_t), intent(inout) :: poses(size(mech%dyads))
    !> Geometry error naming the dyad.
    type(error_t), allocatable, intent(out) :: error
    !> Whether every link's angle is wanted (default true; false: only those a later dyad
    !> turns its guide with, see assur_step_t%link_angles).
    logical, intent(in), optional :: link_angles
    integer :: d
    logical :: all_angles
    all_angles = .true.
    if (present(link_angles)) all_angles = link_angles
    states(0) = link_state_t()  ! the frame: at rest at the origin (frame_state)
    call set_crank_state(mech%pivot, phi1, states(1))
    do d = 1, size(mech%dyads)
      associate (dy => mech%dyads(d))
        call set_dyad_pose(dy%geom, states(dy%on(1)), dy%at(:, 1), dy%ang(1), &
                           states(dy%on(2)), dy%at(:, 2), dy%ang(2), poses(d), all_angles .or. turns_a_guide(mech, d))
        if (poses(d)%status /= pose_ok) then
          if (poses(d)%status == pose_no_assembly) then
            if (allocated(poses(d)%detail)) then
              call fatal_error(error, exit_geometry, dyad_label(mech, d)//": cannot be assembled: "//poses(d)%detail)
            else
              call fatal_error(error, exit_geometry, dyad_label(mech, d)//": cannot be assembled")
            end if
          else
            call fatal_error(error, exit_geometry, dyad_label(mech, d)// &
              ": dead (toggle) position, transfer functions undetermined")
          end if
          return
        end if
        states(link_a(d)) = poses(d)%link(1)
        states(link_b(d)) = poses(d)%link(2)
      end associate
    end do
  end subroutine assur_kinematics

  !> Whether a dyad after dyad `d` has a guide on one of its links (a prismatic outer pair
  !> whose direction turns with that link's angle).
  pure logical function turns_a_guide(mech, d) result(turns)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Dyad number.
    integer, intent(in) :: d
    integer :: dd
    turns = .false.
    do dd = d + 1, size(mech%dyads)
      associate (kind => mech%dyads(dd)%geom%kind, on => mech%dyads(dd)%on)
        if (kind == kind_prp .and. (on(1) == link_a(d) .or. on(1) == link_b(d))) turns = .true.
        if ((kind == kind_rrp .or. kind == kind_prp .or. kind == kind_rpp) .and. &
            (on(2) == link_a(d) .or. on(2) == link_b(d))) turns = .true.
      end associate
    end do
  end function turns_a_guide

  !> Kinetostatic analysis at crank angle `phi1` (rad), crank speed `omega1` (rad/s) and
  !> acceleration `eps1` (rad/s^2), with the external forces' magnitudes `f_mag` (N) and
  !> the external moments `m_mag` (N*m, CCW positive) of this step. Optional `extra` loads
  !> (e.g. friction, see kinetostat_assur_friction) act on the moving links besides the
  !> applied ones, with their virtual power per unit crank speed `extra_power` (N*m) and the
  !> sum of its terms' magnitudes `extra_scale`; `balances` returns every link's loads.
  pure subroutine assur_step(mech, phi1, omega1, eps1, f_mag, m_mag, step, error, extra, extra_power, &
                             extra_scale, balances)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Crank speed, rad/s.
    real(wp), intent(in) :: omega1
    !> Crank angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps1
    !> Magnitudes of the external forces at this step, N.
    real(wp), intent(in) :: f_mag(:)
    !> External moments at this step, N*m.
    real(wp), intent(in) :: m_mag(:)
    !> Results (arrays of the right size it has already are reused).
    type(assur_step_t), intent(inout) :: step
    !> Geometry error (cannot assemble, dead position, undetermined reactions).
    type(error_t), allocatable, intent(out) :: error
    !> Further loads on links 0..2*nd+1 (moments about each link's origin), N and N*m.
    type(link_balance_t), intent(in), optional :: extra(0:)
    !> Virtual power of `extra` per unit crank speed, N*m.
    real(wp), intent(in), optional :: extra_power
    !> Sum of the magnitudes of the terms of `extra_power`, N*m.
    real(wp), intent(in), optional :: extra_scale
    !> All loads and reactions of links 0..2*nd+1 as summed for the equilibrium residual.
    type(link_balance_t), intent(out), optional :: balances(0:)
    real(wp) :: power, power_scale
    integer :: nd, i, nf, k

    nd = size(mech%dyads)
    nf = size(mech%forces)
    call reset_step(step, 3 * nd + 1)
    ! the links' frames, the dyads' poses and the links' loads: the workspace kept in `step`
    ! from the step solved into it before (allocated once for a mechanism, no heap per step;
    ! used in place, not moved out and back: a move of an array's descriptor costs more than
    ! a small mechanism's step takes)
    if (allocated(step%work_states)) then
      if (size(step%work_states) /= 2 * nd + 2 .or. size(step%work_poses) /= nd) then
        deallocate (step%work_states, step%work_poses, step%work_known, step%work_f_len)
      end if
    end if
    if (.not. allocated(step%work_states)) then
      allocate (step%work_states(0:2 * nd + 1), step%work_poses(nd), step%work_known(0:2 * nd + 1), &
                step%work_f_len(3 * nd + 1))
    end if
    if (allocated(step%work_force_angle)) then
      if (size(step%work_force_angle) /= nf) deallocate (step%work_force_angle, step%work_force_dir)
    end if
    if (.not. allocated(step%work_force_angle)) then
      allocate (step%work_force_angle(nf), step%work_force_dir(2, nf))
      do i = 1, nf
        step%work_force_angle(i) = mech%forces(i)%angle
        step%work_force_dir(:, i) = unit_at(step%work_force_angle(i))
      end do
    end if
    do i = 1, nf
      if (step%work_force_angle(i) /= mech%forces(i)%angle) then
        step%work_force_angle(i) = mech%forces(i)%angle
        step%work_force_dir(:, i) = unit_at(step%work_force_angle(i))
      end if
    end do
    ! the frames and poses are set by the kinematics, the loads summed from zero by
    ! applied_loads; the sums run in applied_loads and link_equilibrium, which take the
    ! workspace as explicit shapes (an allocatable component's descriptor read again at every
    ! use costs a small mechanism's step more than its sums)
    associate (states => step%work_states, poses => step%work_poses, known => step%work_known, &
               f_len => step%work_f_len)
      step%phi1 = phi1
      step%omega1 = omega1
      step%eps1 = eps1
      call assur_kinematics(mech, phi1, states, poses, error, step%link_angles)
      if (allocated(error)) return

      ! applied loads on every moving link, summed about the link's origin; power terms
      call applied_loads(mech, omega1, eps1, f_mag, m_mag, states, step%work_force_dir, known, power, power_scale)
      if (present(extra)) then
        do k = 1, ubound(states, 1)
          call balance_add_balance(known(k), extra(k))
        end do
      end if
      if (present(extra_power)) power = power + extra_power
      if (present(extra_scale)) power_scale = power_scale + extra_scale
      ! the size of a driving effort these loads make
      if (mech%drive_dyad == 0) then
        step%load_scale = load_moment_scale(known(1:), mechanism_size(mech, poses))
      else
        step%load_scale = maxval(known(1:)%scale_f)
      end if

      if (mech%drive_dyad == 0) then
        ! dyads from the last to the first; each passes its outer reactions to the links it hangs on
        call back_substitute(mech, states, poses, known, step%f, step%n, step%m, error, f_len)
        if (allocated(error)) return
        ! crank: pin reaction from the frame and balancing moment about the pivot
        step%m1 = -known(1)%sum_m
        step%m1_power = -power
        step%mismatch = power_mismatch(step%m1, step%m1_power, power_scale, step%load_scale)
      else
        call drive_by_actuator(mech, power, power_scale, step, error)
        if (allocated(error)) return
        do k = 1, size(f_len)
          f_len(k) = fast_magnitude(step%f(:, k))
        end do
      end if
      step%power_scale = power_scale

      call link_equilibrium(mech, known, states, poses, step%f, step%m, f_len, step%m1, step%residual)
      if (present(balances)) balances = known
    end associate
  end subroutine assur_step

  !> `step` as a fresh assur_step_t (every scalar at its default) with its pair arrays for
  !> `np` pairs, reusing arrays of that size it already has (zero when new; the solve sets
  !> every entry but the crank pin's n and m, which stay 0; after an error they hold a
  !> partial solve). (The scalars one by one:
  !> an assignment of a fresh assur_step_t would copy and free its arrays every step.)
  pure subroutine reset_step(step, np)
    !> The step.
    type(assur_step_t), intent(inout) :: step
    !> Number of result pairs.
    integer, intent(in) :: np
    step%phi1 = 0.0_wp
    step%omega1 = 0.0_wp
    step%eps1 = 0.0_wp
    step%m1 = 0.0_wp
    step%m1_power = 0.0_wp
    step%residual = 0.0_wp
    step%mismatch = 0.0_wp
    step%power_scale = 0.0_wp
    step%load_scale = 0.0_wp
    step%f_drive = 0.0_wp
    step%f_drive_power = 0.0_wp
    step%stroke = 0.0_wp
    step%stroke_v = 0.0_wp
    step%stroke_a = 0.0_wp
    if (allocated(step%f)) then
      if (size(step%f, 2) /= np) deallocate (step%f)
    end if
    if (allocated(step%n)) then
      if (size(step%n) /= np) deallocate (step%n)
    end if
    if (allocated(step%m)) then
      if (size(step%m) /= np) deallocate (step%m)
    end if
    ! zero when allocated; reused arrays are not cleared again (three calls of memset a step):
    ! the solve sets every pair force and every dyad pair's normal force and moment, and the
    ! crank pin's normal force and moment are never set (they stay 0)
    if (.not. allocated(step%f)) allocate (step%f(2, np), source=0.0_wp)
    if (.not. allocated(step%n)) allocate (step%n(np), source=0.0_wp)
    if (.not. allocated(step%m)) allocate (step%m(np), source=0.0_wp)
  end subroutine reset_step

  !> The applied loads of every moving link into `known` (from zero; forces and moments about
  !> the link's origin): weights, d'Alembert forces and moments, the external forces (given
  !> magnitudes `f_mag`, N, directions `force_dir`) and moments (`m_mag`, N*m); their virtual
  !> power per unit crank speed `power` (N*m) and the sum of its terms' magnitudes
  !> `power_scale` (N*m).
  pure subroutine applied_loads(mech, omega1, eps1, f_mag, m_mag, states, force_dir, known, power, power_scale)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Crank speed, rad/s, and angular acceleration, rad/s^2.
    real(wp), intent(in) :: omega1, eps1
    !> Magnitudes of the external forces, N.
    real(wp), intent(in) :: f_mag(:)
    !> External moments, N*m.
    real(wp), intent(in) :: m_mag(:)
    !> Frames of links 0..2*nd+1.
    type(link_state_t), intent(in) :: states(0:2 * size(mech%dyads) + 1)
    !> [cos, sin] of each external force's angle.
    real(wp), intent(in) :: force_dir(2, size(mech%forces))
    !> Loads of every link (N, N*m about its origin).
    type(link_balance_t), intent(inout) :: known(0:2 * size(mech%dyads) + 1)
    !> Virtual power of the loads per unit crank speed and the sum of its terms' magnitudes, N*m.
    real(wp), intent(out) :: power, power_scale
    type(point_state_t) :: ps
    real(wp) :: w2, a_s(2), eps, phi_f(2), gw(2), m_phi, dir(2), term
    integer :: i, k

    ! the loads are sums, from zero (each moving link's zeroed in the loop that adds its own)
    known(0) = link_balance_t()
    w2 = omega1**2
    power = 0.0_wp
    power_scale = 0.0_wp
    do i = 1, ubound(states, 1)
      associate (lk => mech%links(i), st => states(i))
        known(i) = link_balance_t()
        call point_motion(st, lk%s, ps)
        a_s = ps%a * w2 + ps%v * eps1
        eps = st%eq * w2 + st%u * eps1
        gw = gravity_force(lk%m, mech%g, mech%down)
        phi_f = inertia_force(lk%m, a_s)
        m_phi = inertia_moment(lk%j, eps)
        call balance_add_force(known(i), st%o, ps%p, gw + phi_f)
        call balance_add_couple(known(i), m_phi)
        term = dot_product(gw + phi_f, ps%v)
        power = power + term + m_phi * st%u
        power_scale = power_scale + abs(term) + abs(m_phi * st%u)
      end associate
    end do
    do k = 1, size(mech%forces)
      associate (fo => mech%forces(k))
        i = fo%link
        call point_motion(states(i), fo%at, ps)
        if (fo%follow) then
          ! the force's own direction turned by the link's angle (its cos and sin at hand)
          associate (e => force_dir(:, k), c => states(i)%cos_th, s => states(i)%sin_th)
            dir = [c * e(1) - s * e(2), s * e(1) + c * e(2)]
          end associate
        else
          dir = force_dir(:, k)
        end if
        call balance_add_force(known(i), states(i)%o, ps%p, f_mag(k) * dir)
        term = dot_product(f_mag(k) * dir, ps%v)
        power = power + term
        power_scale = power_scale + abs(term)
      end associate
    end do
    do k = 1, size(mech%moment_link)
      i = mech%moment_link(k)
      call balance_add_couple(known(i), m_mag(k))
      power = power + m_mag(k) * states(i)%u
      power_scale = power_scale + abs(m_mag(k) * states(i)%u)
    end do
  end subroutine applied_loads

  !> The self-check's equilibrium: every pair's reaction added to both links it acts between
  !> (the crank's pin and balancing moment `m1` to the crank) in `known`, which holds the
  !> applied loads and the reactions passed back; `residual` is the largest relative
  !> equilibrium residual of the moving links. Each pair force goes into a local pair first
  !> (its negation in place would be a temporary).
  pure subroutine link_equilibrium(mech, known, states, poses, f, m, f_len, m1, residual)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Loads of every link (N, N*m about its origin); the reactions are added.
    type(link_balance_t), intent(inout) :: known(0:2 * size(mech%dyads) + 1)
    !> Frames of links 0..2*nd+1.
    type(link_state_t), intent(in) :: states(0:2 * size(mech%dyads) + 1)
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(size(mech%dyads))
    !> Pair forces (dyad pairs, then the crank pin), N.
    real(wp), intent(in) :: f(2, 3 * size(mech%dyads) + 1)
    !> Reaction moments of prismatic pairs, N*m.
    real(wp), intent(in) :: m(3 * size(mech%dyads) + 1)
    !> Length of each pair force as fast_magnitude gives it, N.
    real(wp), intent(in) :: f_len(3 * size(mech%dyads) + 1)
    !> Balancing moment on the crank, N*m.
    real(wp), intent(in) :: m1
    !> Largest relative equilibrium residual of the moving links.
    real(wp), intent(out) :: residual
    real(wp) :: f_pair(2)
    integer :: d, nd, ip, pa, pb
    nd = size(mech%dyads)
    ip = crank_pin_index(nd)
    f_pair = f(:, ip)
    call balance_add_force(known(1), states(1)%o, states(1)%o, f_pair, f_len(ip))
    call balance_add_couple(known(1), m1)
    do d = 1, nd
      pa = link_a(d)
      pb = link_b(d)
      ip = pair_index(d, 1)
      f_pair = f(:, ip)
      call balance_add_force(known(pa), states(pa)%o, poses(d)%p(:, 1), f_pair, f_len(ip))
      call balance_add_couple(known(pa), m(ip))
      ip = pair_index(d, 2)
      f_pair = f(:, ip)
      call balance_add_force(known(pa), states(pa)%o, poses(d)%p(:, 2), f_pair, f_len(ip))
      call balance_add_couple(known(pa), m(ip))
      f_pair = -f_pair
      call balance_add_force(known(pb), states(pb)%o, poses(d)%p(:, 2), f_pair, f_len(ip))
      call balance_add_couple(known(pb), -m(ip))
      ip = pair_index(d, 3)
      f_pair = f(:, ip)
      call balance_add_force(known(pb), states(pb)%o, poses(d)%p(:, 3), f_pair, f_len(ip))
      call balance_add_couple(known(pb), m(ip))
    end do
    residual = equilibrium_residual(known(1:))
  end subroutine link_equilibrium

  !> Size of the mechanism at this position: the largest distance of a dyad's joint from
  !> the crank pivot, m (a lever arm of the driving moment).
  pure real(wp) function mechanism_size(mech, poses) result(length)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(size(mech%dyads))
    !> The largest squared distance, m^2, and the point at that distance.
    real(wp) :: sq, sq_max, far(2)
    integer :: d, j
    ! the square root of the largest square (the root is monotonic and correctly rounded:
    ! the largest of the roots, one root instead of one a joint)
    sq_max = -1.0_wp
    far = 0.0_wp
    do d = 1, size(poses)
      do j = 1, size(poses(d)%p, 2)
        sq = (poses(d)%p(1, j) - mech%pivot(1))**2 + (poses(d)%p(2, j) - mech%pivot(2))**2
        if (sq > sq_max) then
          sq_max = sq
          far = poses(d)%p(:, j) - mech%pivot
        end if
      end do
    end do
    length = fast_magnitude(far)
    ! squares outside fast_magnitude's range (where it takes hypot): the lengths one by one
    if (.not. (sq_max >= 1.0e-290_wp .and. sq_max <= 1.0e290_wp)) then
      length = 0.0_wp
      do d = 1, size(poses)
        do j = 1, size(poses(d)%p, 2)
          length = max(length, fast_magnitude(poses(d)%p(:, j) - mech%pivot))
        end do
      end do
    end if
  end function mechanism_size

  !> The pair whose stroke is the position of link `i` (internal index): the prismatic pair
  !> by which it slides on a frame guide (link a: pair 1, link b: pair 3), else 0 (the
  !> link's position is its angle).
  pure integer function output_pair_of(mech, i) result(j)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Internal link index (>= 1).
    integer, intent(in) :: i
    integer :: d
    j = 0
    if (i < 2) return
    d = i / 2
    if (i == link_a(d)) then
      if (mech%dyads(d)%on(1) == 0 .and. pair_is_prismatic(mech%dyads(d)%geom%kind, 1)) j = 1
    else
      if (mech%dyads(d)%on(2) == 0 .and. pair_is_prismatic(mech%dyads(d)%geom%kind, 3)) j = 3
    end if
  end function output_pair_of

  !> Position of the output link with its analogues: its angle (rad, rad/rad, rad/rad^2), or
  !> for a slider on a frame guide its stroke along the guide (m, m/rad, m/rad^2).
  pure subroutine output_position(mech, states, poses, q, dq, ddq)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Frames of links 0..2*nd+1.
    type(link_state_t), intent(in) :: states(0:)
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(:)
    !> Position, its first and second analogues.
    real(wp), intent(out) :: q, dq, ddq
    call link_position(states, poses, mech%output_link, mech%output_pair, q, dq, ddq)
  end subroutine output_position

  !> Position of link `i` with its analogues: its angle (`pair` = 0; rad, rad/rad,
  !> rad/rad^2) or the stroke of pair `pair` of its dyad (m, m/rad, m/rad^2).
  pure subroutine link_position(states, poses, i, pair, q, dq, ddq)
    !> Frames of links 0..2*nd+1.
    type(link_state_t), intent(in) :: states(0:)
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(:)
    !> Internal link index; 0 or the pair of its dyad whose stroke is its position.
    integer, intent(in) :: i, pair
    !> Position, its first and second analogues.
    real(wp), intent(out) :: q, dq, ddq
    if (pair == 0) then
      q = states(i)%th
      dq = states(i)%u
      ddq = states(i)%eq
    else
      q = poses(i / 2)%stroke(pair)
      dq = poses(i / 2)%stroke_v(pair)
      ddq = poses(i / 2)%stroke_a(pair)
    end if
  end subroutine link_position

  !> The first extreme position of the output link (its position's analogue changes sign)
  !> at or after crank angle `phi_from` (rad), within one turn: a scan in 0.5 deg steps over
  !> the assembled positions, then bisection to roundoff.
  pure subroutine assur_extreme(mech, phi_from, phi, error)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Where the search starts, rad.
    real(wp), intent(in) :: phi_from
    !> Crank angle of the extreme position, rad.
    real(wp), intent(out) :: phi
    !> Geometry error when there is none within one turn.
    type(error_t), allocatable, intent(out) :: error
    integer, parameter :: n_scan = 720
    real(wp), parameter :: two_pi = 8.0_wp * atan(1.0_wp)
    real(wp) :: x, dq, prev_dq, prev_x, lo, hi, dq_lo, mid, dq_mid
    logical :: prev_ok, ok
    integer :: k, it
    phi = phi_from
    prev_ok = .false.
    prev_dq = 0.0_wp
    prev_x = phi_from
    do k = 0, n_scan
      x = phi_from + two_pi * real(k, wp) / real(n_scan, wp)
      call output_rate(mech, x, dq, ok)
      if (.not. ok) then
        prev_ok = .false.
        cycle
      end if
      if (dq == 0.0_wp) then
        phi = x
        return
      end if
      if (prev_ok .and. sign(1.0_wp, dq) /= sign(1.0_wp, prev_dq)) then
        lo = prev_x
        hi = x
        dq_lo = prev_dq
        do it = 1, 200
          mid = 0.5_wp * (lo + hi)
          if (mid <= lo .or. mid >= hi) exit
          call output_rate(mech, mid, dq_mid, ok)
          if (.not. ok) exit
          if (dq_mid == 0.0_wp) then
            lo = mid
            hi = mid
            exit
          end if
          if (sign(1.0_wp, dq_mid) == sign(1.0_wp, dq_lo)) then
            lo = mid
            dq_lo = dq_mid
          else
            hi = mid
          end if
        end do
        phi = 0.5_wp * (lo + hi)
        return
      end if
      prev_ok = .true.
      prev_dq = dq
      prev_x = x
    end do
    call fatal_error(error, exit_geometry, "no extreme position of link "//int_str(mech%links(mech%output_link)%id)// &
      " (the output link) within one turn of the crank")
  end subroutine assur_extreme

  !> The output position's first analogue `dq` at crank angle `phi` (rad); `ok` false where
  !> the mechanism cannot be assembled.
  pure subroutine output_rate(mech, phi, dq, ok)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Crank angle, rad.
    real(wp), intent(in) :: phi
    !> d(output position)/d phi1 (rad/rad or m/rad).
    real(wp), intent(out) :: dq
    !> Whether the mechanism is assembled there.
    logical, intent(out) :: ok
    type(link_state_t) :: states(0:2 * size(mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(mech%dyads))
    type(error_t), allocatable :: error
    real(wp) :: q, ddq
    dq = 0.0_wp
    call assur_kinematics(mech, phi, states, poses, error)
    ok = .not. allocated(error)
    if (ok) call output_position(mech, states, poses, q, dq, ddq)
  end subroutine output_rate

  !> Internal indices of the two sides of pair `j` of dyad `d`: (1) the sliding side (the
  !> dyad's link a for pairs 1 and 2, link b for pair 3), (2) the other side.
  pure function pair_sides(mech, d, j) result(sides)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Dyad number.
    integer, intent(in) :: d
    !> Pair: 1 outer of a, 2 inner, 3 outer of b.
    integer, intent(in) :: j
    integer :: sides(2)
    select case (j)
    case (1)
      sides = [link_a(d), mech%dyads(d)%on(1)]
    case (2)
      sides = [link_a(d), link_b(d)]
    case default
      sides = [link_b(d), mech%dyads(d)%on(2)]
    end select
  end function pair_sides

  !> Reactions of every dyad from the last to the first, each passing its outer reactions to
  !> the links it hangs on (`known` holds every link's loads about its origin and receives
  !> them); then the crank pin's reaction `f(:, crank pin)`. The crank's remaining moment is
  !> `known(1)%sum_m`. `f_len` receives every pair force's fast_magnitude.
  pure subroutine back_substitute(mech, states, poses, known, f, n, m, error, f_len)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Frames of links 0..2*nd+1 (explicit shapes here: a step's arrays are contiguous, and
    !> the strides of assumed shapes cost a small mechanism's step more than its sums).
    type(link_state_t), intent(in) :: states(0:2 * size(mech%dyads) + 1)
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(size(mech%dyads))
    !> Loads of every link (N, N*m about its origin); reactions of later dyads are added.
    type(link_balance_t), intent(inout) :: known(0:2 * size(mech%dyads) + 1)
    !> Pair forces (dyad pairs, then the crank pin), N.
    real(wp), intent(inout) :: f(2, 3 * size(mech%dyads) + 1)
    !> Signed normal forces of prismatic pairs, N.
    real(wp), intent(inout) :: n(3 * size(mech%dyads) + 1)
    !> Reaction moments of prismatic pairs, N*m.
    real(wp), intent(inout) :: m(3 * size(mech%dyads) + 1)
    !> Geometry error naming the dyad.
    type(error_t), allocatable, intent(out) :: error
    !> Length of each pair force (dyad pairs, then the crank pin) as fast_magnitude gives it, N.
    real(wp), intent(out), optional :: f_len(3 * size(mech%dyads) + 1)
    type(dyad_reactions_t) :: r
    real(wp) :: lengths(3)
    type(error_t), allocatable :: solve_error
    real(wp) :: f_known(2, 2), m_known(2), o(2)
    integer :: d, nd, q, i, jp
    nd = size(mech%dyads)
    do d = nd, 1, -1
      o = poses(d)%p(:, 2)
      do q = 1, 2
        i = 2 * d + q - 1
        f_known(:, q) = known(i)%sum_f
        m_known(q) = known(i)%sum_m + cross(states(i)%o - o, known(i)%sum_f)
      end do
      call dyad_reactions(mech%dyads(d)%geom%kind, poses(d)%p, poses(d)%t, o, f_known, m_known, r, solve_error)
      if (allocated(solve_error)) then
        call fatal_error(error, exit_geometry, dyad_label(mech, d)//": reactions undetermined, "// &
                         solve_error%message)
        return
      end if
      do jp = 1, 3
        f(:, pair_index(d, jp)) = r%f(:, jp)
        n(pair_index(d, jp)) = r%n(jp)
        m(pair_index(d, jp)) = r%m(jp)
        lengths(jp) = fast_magnitude(r%f(:, jp))
      end do
      if (present(f_len)) f_len(pair_index(d, 1):pair_index(d, 3)) = lengths
      call pass_reactions(mech, states, poses, d, r%f, r%m, known, lengths)
    end do
    f(:, crank_pin_index(nd)) = -known(1)%sum_f
    if (present(f_len)) f_len(crank_pin_index(nd)) = fast_magnitude(f(:, crank_pin_index(nd)))
  end subroutine back_substitute

  !> The outer reactions of dyad `d` acting back on the links it hangs on (action = -reaction,
  !> couples too); the frame (index 0) takes nothing.
  pure subroutine pass_reactions(mech, states, poses, d, f, m, known, f_len)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Frames of links 0..2*nd+1.
    type(link_state_t), intent(in) :: states(0:2 * size(mech%dyads) + 1)
    !> Pose of each dyad.
    type(dyad_pose_t), intent(in) :: poses(size(mech%dyads))
    !> Dyad number.
    integer, intent(in) :: d
    !> Forces of the dyad's pairs 1..3 (pair 1 on a, pair 3 on b), N.
    real(wp), intent(in) :: f(2, 3)
    !> Reaction moments of the dyad's pairs 1..3, N*m.
    real(wp), intent(in) :: m(3)
    !> Loads of every link.
    type(link_balance_t), intent(inout) :: known(0:2 * size(mech%dyads) + 1)
    !> fast_magnitude of the forces of pairs 1..3 when known, N.
    real(wp), intent(in), optional :: f_len(3)
    integer :: q, i, jp
    integer, parameter :: pair_of_link(2) = [1, 3]
    do q = 1, 2
      jp = pair_of_link(q)
      i = mech%dyads(d)%on(q)
      if (i == 0) cycle
      if (present(f_len)) then
        call balance_add_force(known(i), states(i)%o, poses(d)%p(:, jp), -f(:, jp), f_len(jp))
      else
        call balance_add_force(known(i), states(i)%o, poses(d)%p(:, jp), -f(:, jp))
      end if
      call balance_add_couple(known(i), -m(jp))
    end do
  end subroutine pass_reactions

  !> A linear actuator drives: the axial force F_drive of the driving prismatic pair (pushing
  !> its sliding side along `extend`, the other side back) is the unknown and the crank
  !> carries no balancing moment. Reactions are linear in the loads: one pass with the applied
  !> loads (crank moment M0), one with a unit actuator force (Mu); F_drive = -M0/Mu. Mu is
  !> -stroke' by virtual work, so Mu = 0 is a dead position of the actuator. Self-check: the
  !> power balance F_drive*stroke' + sum of the loads' powers = 0. On return `step%work_known` holds the
  !> applied loads, the actuator's forces and the reactions passed back by every dyad.
  pure subroutine drive_by_actuator(mech, power, power_scale, step, error)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Power analogue of the applied loads (N*m per rad of phi1) and its scale.
    real(wp), intent(in) :: power, power_scale
    !> Results (f, n, m allocated and zero), with the frames of links 0..2*nd+1
    !> (work_states), the pose of each dyad (work_poses) and the applied loads of every link
    !> (work_known: N, N*m about its origin).
    type(assur_step_t), intent(inout) :: step
    !> Geometry error.
    type(error_t), allocatable, intent(out) :: error
    type(link_balance_t) :: applied(0:ubound(step%work_known, 1)), unit(0:ubound(step%work_known, 1))
    real(wp) :: fu(2, size(step%f, 2)), nu(size(step%n)), mu(size(step%m)), extend(2), at(2)
    real(wp) :: m1_loads, m1_unit, lever, ds
    integer :: sides(2), dd, jd, d, nd
    associate (states => step%work_states, poses => step%work_poses, known => step%work_known)
      nd = size(mech%dyads)
      dd = mech%drive_dyad
      jd = mech%drive_pair
      sides = pair_sides(mech, dd, jd)
      extend = poses(dd)%extend(:, jd)
      at = poses(dd)%p(:, jd)
      applied = known
      call balance_add_force(unit(sides(1)), states(sides(1))%o, at, extend)
      call balance_add_force(unit(sides(2)), states(sides(2))%o, at, -extend)
      fu = 0.0_wp
      nu = 0.0_wp
      mu = 0.0_wp
      call back_substitute(mech, states, poses, known, step%f, step%n, step%m, error)
      if (allocated(error)) return
      call back_substitute(mech, states, poses, unit, fu, nu, mu, error)
      if (allocated(error)) return
      m1_loads = -known(1)%sum_m
      m1_unit = -unit(1)%sum_m
      lever = 0.0_wp
      do d = 1, 3
        lever = max(lever, magnitude(poses(dd)%p(:, d) - mech%pivot))
      end do
      if (.not. abs(m1_unit) > drive_dead_rel * lever) then
        call fatal_error(error, exit_geometry, dyad_label(mech, dd)//": the actuator (pair "//int_str(jd)// &
          ") cannot move the input link here (dead position: |stroke'| = "//trimmed_es(abs(m1_unit), 3)//" m/rad)")
        return
      end if
      step%f_drive = -m1_loads / m1_unit
      step%f = step%f + step%f_drive * fu
      step%n = step%n + step%f_drive * nu
      step%m = step%m + step%f_drive * mu
      step%m1 = 0.0_wp
      ds = poses(dd)%stroke_v(jd)
      step%stroke = poses(dd)%stroke(jd)
      step%stroke_v = ds * step%omega1
      step%stroke_a = poses(dd)%stroke_a(jd) * step%omega1**2 + ds * step%eps1
      step%f_drive_power = -power / ds
      step%mismatch = power_mismatch(step%f_drive, step%f_drive_power, power_scale / abs(ds), step%load_scale)
      ! every link's loads with the final reactions, for the equilibrium residual
      known = applied
      call balance_add_force(known(sides(1)), states(sides(1))%o, at, step%f_drive * extend)
      call balance_add_force(known(sides(2)), states(sides(2))%o, at, -step%f_drive * extend)
      do d = nd, 1, -1
        call pass_reactions(mech, states, poses, d, step%f(:, pair_index(d, 1):pair_index(d, 3)), &
                            step%m(pair_index(d, 1):pair_index(d, 3)), known)
      end do
    end associate
  end subroutine drive_by_actuator

end module kinetostat_assur
