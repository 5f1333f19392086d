!> The machine dynamics of a `&linkage` deck with one drive: its reduced quantities at an
!> assembled pose (J_red = sum m |v_S|^2 + J u^2, dJ_red = sum 2 m v_S . a_S + 2 J u eps_q,
!> M_red = sum F . v + M u over gravity, the forces and the moments, from the velocity and
!> acceleration analogues of the pose solve: dq/d(drive) and d2q/d(drive)^2), and the reduced
!> quantities at any drive angle for the steady cycle (a reduced_source_t): the poses are
!> assembled once over the cycle every 0.5 deg (the continuation of the run), and a pose at
!> any angle by Newton's method from the nearest of them. Loops whose sums reach a printed
!> digit stay scalar (`!GCC$ novector`: the release build writes the debug build's digits).
module kinetostat_linkage_dynamics
  use kinetostat_kinds, only: wp, rad_to_deg, deg_to_rad, pi
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: real_str
  use kinetostat_vec2, only: rotate
  use kinetostat_dynamics, only: reduced_t, reduced_source_t
  use kinetostat_linkage, only: linkage_t, linkage_work_t, linkage_assemble, linkage_motion, link_point_state, &
    linkage_reference_pose
  use kinetostat_linkage_deck, only: linkage_deck_t, linkage_schedule_at, linkage_table_position
  implicit none
  private
  public :: linkage_source_t, linkage_source_setup, linkage_reduced_at_pose, linkage_load_breaks, linkage_source_at

  !> Spacing of the cycle's stored poses, rad (0.5 deg).
  real(wp), parameter :: pose_step = 0.5_wp * pi / 180.0_wp

  !> The reduced quantities of a `&linkage` deck (one turning drive) at any drive angle.
  type, extends(reduced_source_t) :: linkage_source_t
    !> The validated deck.
    type(linkage_deck_t) :: deck
    !> First drive angle of the cycle and the spacing of the stored poses, rad.
    real(wp) :: phi0 = 0.0_wp, h = pose_step
    !> The poses at phi0 + j h, j = 0..m (3n, 0:m).
    real(wp), allocatable :: poses(:, :)
  contains
    procedure :: at, failure
  end type linkage_source_t

contains

  !> The stored poses of the cycle phi0 .. phi0 + span (rad) of the deck's first drive,
  !> assembled from the reference position; `where` ("deck: &linkage") names the deck.
  pure subroutine linkage_source_setup(deck, phi0, span, where, source, error)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), intent(in) :: phi0, span
    character(*), intent(in) :: where
    type(linkage_source_t), intent(out) :: source
    type(error_t), allocatable, intent(out) :: error
    type(linkage_work_t) :: work
    real(wp), allocatable :: q(:)
    real(wp) :: from
    integer :: m, j
    source%deck = deck
    source%phi0 = phi0
    m = max(1, ceiling(span / pose_step - 1.0e-9_wp))
    source%h = span / real(m, wp)
    allocate (source%poses(3 * size(deck%mech%links), 0:m))
    q = linkage_reference_pose(deck%mech)
    from = deck%mech%drives(1)%q_ref
    !GCC$ novector
    do j = 0, m
      call linkage_assemble(deck%mech, [from], [phi0 + real(j, wp) * source%h], q, work, error)
      if (allocated(error)) then
        error%message = where//": dynamics: the cycle at phi1 = "//real_str((phi0 + real(j, wp) * source%h) * &
          rad_to_deg)//" deg: "//error%message
        error%code = exit_geometry
        return
      end if
      from = phi0 + real(j, wp) * source%h
      source%poses(:, j) = q
    end do
  end subroutine linkage_source_setup

  !> The pose at drive angle phi (rad): Newton's method from the nearest stored pose.
  pure subroutine pose_at(self, phi, q, work, error)
    class(linkage_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    real(wp), allocatable, intent(out) :: q(:)
    !> The kernel's workspace (J and its factors at q on return).
    type(linkage_work_t), intent(inout) :: work
    type(error_t), allocatable, intent(out) :: error
    integer :: j, m
    m = ubound(self%poses, 2)
    j = min(m, max(0, nint((phi - self%phi0) / self%h)))
    q = self%poses(:, j)
    call linkage_assemble(self%deck%mech, [self%phi0 + real(j, wp) * self%h], [phi], q, work, error)
  end subroutine pose_at

  !> J_red (links only), dJ_red, M_red at drive angle phi (rad), the loads at that angle.
  pure function at(self, phi) result(red)
    class(linkage_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    type(reduced_t) :: red
    type(linkage_work_t) :: work
    call linkage_source_at(self, phi, work, red)
  end function at

  !> `at` with the caller's workspace (a run of angles allocates it once; the same values).
  pure subroutine linkage_source_at(self, phi, work, red)
    class(linkage_source_t), intent(in) :: self
    !> Drive angle, rad.
    real(wp), intent(in) :: phi
    !> The kernel's workspace.
    type(linkage_work_t), intent(inout) :: work
    !> The reduced quantities (not ok where the linkage cannot be assembled).
    type(reduced_t), intent(out) :: red
    real(wp), allocatable :: q(:), fval(:), mval(:)
    type(error_t), allocatable :: error
    integer :: i
    call pose_at(self, phi, q, work, error)
    if (allocated(error)) then
      red%ok = .false.
      return
    end if
    allocate (fval(size(self%deck%force_load)), mval(size(self%deck%moment_load)))
    !GCC$ novector
    do i = 1, size(fval)
      fval(i) = linkage_schedule_at(self%deck%force_load(i), phi * rad_to_deg, &
        linkage_table_position(self%deck%mech, self%deck%force_load(i), q))
    end do
    !GCC$ novector
    do i = 1, size(mval)
      mval(i) = linkage_schedule_at(self%deck%moment_load(i), phi * rad_to_deg, &
        linkage_table_position(self%deck%mech, self%deck%moment_load(i), q))
    end do
    call reduced_at_pose(self%deck%mech, q, fval, mval, work, red)
  end subroutine linkage_source_at

  !> Why there are no reduced quantities at phi (rad): the pose solve's message.
  pure function failure(self, phi) result(text)
    class(linkage_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    character(len=:), allocatable :: text
    real(wp), allocatable :: q(:)
    type(error_t), allocatable :: error
    type(linkage_work_t) :: work
    text = ""
    call pose_at(self, phi, q, work, error)
    if (allocated(error)) text = error%message
  end function failure

  !> The reduced quantities at assembled poses q of a linkage with one drive (per unit of the
  !> drive: rad or m), the forces' magnitudes fval (N) and the moments mval (N*m); not ok at
  !> a dead position.
  pure function linkage_reduced_at_pose(mech, q, fval, mval) result(red)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), fval(:), mval(:)
    type(reduced_t) :: red
    type(linkage_work_t) :: work
    call reduced_at_pose(mech, q, fval, mval, work, red)
  end function linkage_reduced_at_pose

  !> linkage_reduced_at_pose with the caller's workspace (J's factors at q reused when it
  !> has them).
  pure subroutine reduced_at_pose(mech, q, fval, mval, work, red)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), fval(:), mval(:)
    type(linkage_work_t), intent(inout) :: work
    type(reduced_t), intent(out) :: red
    type(error_t), allocatable :: error
    real(wp) :: v(size(q)), a(size(q)), x(2), vs(2), as(2), w(2)
    integer :: i, k
    call linkage_motion(mech, q, [1.0_wp], [0.0_wp], v, a, work, error)
    if (allocated(error)) then
      red%ok = .false.
      return
    end if
    !GCC$ novector
    do i = 1, size(mech%links)
      associate (lk => mech%links(i))
        call link_point_state(mech, q, v, a, i, lk%s, x, vs, as)
        red%j = red%j + lk%m * dot_product(vs, vs) + lk%j * v(3 * i)**2
        red%dj = red%dj + 2.0_wp * (lk%m * dot_product(vs, as) + lk%j * v(3 * i) * a(3 * i))
        red%m = red%m + lk%m * dot_product(mech%gravity, vs)
      end associate
    end do
    !GCC$ novector
    do k = 1, size(mech%forces)
      associate (fc => mech%forces(k))
        w = fc%dir
        if (fc%follow) w = rotate(fc%dir, q(3 * fc%link))
        call link_point_state(mech, q, v, a, fc%link, fc%at, x, vs, as)
        red%m = red%m + fval(k) * dot_product(w, vs)
      end associate
    end do
    !GCC$ novector
    do k = 1, size(mech%moment_link)
      red%m = red%m + mval(k) * v(3 * mech%moment_link(k))
    end do
  end subroutine reduced_at_pose

  !> The first drive's values where a load switches (its windows' ends, its table's points), rad.
  pure function linkage_load_breaks(deck) result(breaks)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), allocatable :: breaks(:)
    integer :: k
    allocate (breaks(0))
    !GCC$ novector
    do k = 1, size(deck%force_load)
      if (deck%force_load(k)%window) breaks = [breaks, [deck%force_load(k)%phi_on, deck%force_load(k)%phi_off] * deg_to_rad]
      if (deck%force_load(k)%table .and. deck%force_load(k)%link == 0) breaks = [breaks, deck%force_load(k)%x * deg_to_rad]
    end do
    !GCC$ novector
    do k = 1, size(deck%moment_load)
      if (deck%moment_load(k)%window) breaks = [breaks, [deck%moment_load(k)%phi_on, deck%moment_load(k)%phi_off] * &
        deg_to_rad]
      if (deck%moment_load(k)%table .and. deck%moment_load(k)%link == 0) breaks = [breaks, deck%moment_load(k)%x * deg_to_rad]
    end do
  end function linkage_load_breaks

end module kinetostat_linkage_dynamics
