!> `&cam` decks: reading, validation, and the commented template. Per-step data (theta, f2,
!> vdir, ds_dphi) are arrays with one value per cam angle, or a single value for all steps.
module kinetostat_cam_deck
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str, lower
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_deck, only: write_template_lines, deck_context_t, unset_real, deck_array_capacities, &
    deck_source_t, namelist_probe_t, require_all_set, deck_error, is_set, require_set, require_positive, &
    require_nonnegative, require_rule, optional_default, count_values, steps_over_turn
  use kinetostat_cam, only: cam_params_t
  implicit none
  private
  public :: cam_deck_t, read_cam_deck, write_cam_template, follower_translating, follower_flat

  !> Follower: knife-edge or roller, pressure angle from the deck, no friction at the cam.
  integer, parameter :: follower_translating = 1
  !> Follower: flat face normal to its axis, pressure angle 0, friction at the cam.
  integer, parameter :: follower_flat = 2

  !> A validated `&cam` deck.
  type :: cam_deck_t
    !> follower_translating or follower_flat.
    integer :: follower = follower_translating
    !> Guide data, SI.
    type(cam_params_t) :: p
    !> Flat face: friction coefficient cam/follower.
    real(wp) :: f_cam = 0.0_wp
    !> Flat face: +1 cam turns counter-clockwise, -1 clockwise.
    real(wp) :: omega_dir = 1.0_wp
    !> First cam angle, deg.
    real(wp) :: phi_start = 0.0_wp
    !> Cam step, deg.
    real(wp) :: dphi = 0.0_wp
    !> Number of steps.
    integer :: n = 0
    !> Cam angle per step, deg.
    real(wp), allocatable :: phi_deg(:)
    !> Pressure angle per step, deg (flat face: 0).
    real(wp), allocatable :: theta_deg(:)
    !> Follower load per step, N (> 0 presses it onto the cam).
    real(wp), allocatable :: f2(:)
    !> Motion per step: +1 rise, -1 return, 0 at rest.
    real(wp), allocatable :: vdir(:)
    !> Flat face: velocity analogue ds/dphi per step, m/rad (translating: 0).
    real(wp), allocatable :: ds_dphi(:)
    !> Contact offset x_B per step, m (flat face: omega_dir*ds_dphi; translating: 0).
    real(wp), allocatable :: x_b(:)
    !> Signed friction at the cam along +x on the follower (flat face: -omega_dir*f_cam).
    real(wp) :: mu_cam = 0.0_wp
    !> Count of values given for theta, f2, vdir, ds_dphi (1 = constant).
    integer :: given(4) = 0
  end type cam_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: template_lines(*) = [character(len=100) :: &
    "! kinetostat deck: cam with a translating follower in a guide (manual section 7).", &
    "! Guide ends C (near the cam) and D; contact point B an overhang l_over before C.", &
    "! Per-step values: one per cam angle (n values) or one value for every step.", &
    "&cam", &
    "  follower = 'translating'  ! 'translating' (knife/roller: theta given) or 'flat' (flat face)", &
    "  l      = 0.06     ! m, guide length C-D, > 0", &
    "  l_over = 0.04     ! m, overhang B-C along the axis, >= 0", &
    "  f      = 0.15     ! friction coefficient in the guide, >= 0", &
    "  phi_start = 0     ! deg, first cam angle (optional, default 0)", &
    "  dphi   = 30       ! deg, cam step (> 0)", &
    "  n      = 7        ! steps (optional; default 360/dphi + 1)", &
    "  theta  = 0, 12, 24, 30, 24, 12, 0   ! deg, pressure angle, |theta| < 90 (translating)", &
    "  f2     = 400      ! N, load on the follower towards the cam (> 0 keeps contact)", &
    "  vdir   = 1        ! +1 rise, -1 return, 0 at rest (translating; default +1)", &
    "  ! flat face only: f_cam = 0.1 (friction at the cam, >= 0), omega_dir = 1 (+1 CCW,", &
    "  ! -1 CW), ds_dphi = ... (m/rad, velocity analogue; its sign gives rise/return)", &
    "/"]

contains

  !> The commented template deck.
  pure subroutine write_cam_template(out)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    call write_template_lines(out, template_lines)
  end subroutine write_cam_template

  !> Read and validate a `&cam` deck.
  subroutine read_cam_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(cam_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=16) :: follower
    real(wp) :: l, l_over, f, f_cam, omega_dir, phi_start, dphi
    real(wp), allocatable :: theta(:), f2(:), vdir(:), ds_dphi(:)
    !> Number of steps as given (an integer deck variable, read as a real: see require_whole).
    real(wp) :: n
    integer :: ios, k
    !> Elements allocated for each per-step array the deck may give (see deck_array_capacities).
    integer, allocatable :: capacity(:)
    character(len=512) :: msg
    type(deck_context_t) :: ctx
    type(namelist_probe_t) :: probe
    namelist /cam/ follower, l, l_over, f, f_cam, omega_dir, phi_start, dphi, n, theta, f2, vdir, ds_dphi

    ctx%path = source%path
    ctx%group = "cam"
    follower = " "
    l = unset_real; l_over = unset_real; f = unset_real; f_cam = unset_real
    omega_dir = unset_real; phi_start = unset_real; dphi = unset_real
    n = unset_real
    capacity = deck_array_capacities(source, ctx%group, [character(len=7) :: "theta", "f2", "vdir", "ds_dphi"])
    allocate (theta(capacity(1)), f2(capacity(2)), vdir(capacity(3)), ds_dphi(capacity(4)), source=unset_real)

    read (source%lines, nml=cam, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      ! find the line and the assignment that failed (gfortran's message does not say)
      call probe%start(source, ios, msg)
      do while (probe%more(source))
        read (probe%lines, nml=cam, iostat=ios, iomsg=msg)
        call probe%take(ios, msg)
      end do
      call probe%report(source, ctx, error)
      return
    end if

    select case (lower(trim(adjustl(follower))))
    case ("", "translating")
      deck%follower = follower_translating
    case ("flat")
      deck%follower = follower_flat
    case default
      call deck_error(ctx, "follower", "must be 'translating' or 'flat' (got '"//trim(follower)//"')", error)
      return
    end select

    ! every missing required variable in one message
    call require_all_set(ctx, [character(len=6) :: "l", "l_over", "f", "dphi"], &
      [l, l_over, f, dphi], error)
    if (allocated(error)) return

    ! guide
    call require_positive(ctx, "l", l, error); if (allocated(error)) return
    call require_nonnegative(ctx, "l_over", l_over, error); if (allocated(error)) return
    call require_nonnegative(ctx, "f", f, error); if (allocated(error)) return
    deck%p = cam_params_t(l=l, a=l_over, f=f)

    ! cam angles
    phi_start = optional_default(phi_start, 0.0_wp)
    call require_set(ctx, "phi_start", phi_start, error); if (allocated(error)) return
    call steps_over_turn(ctx, dphi, n, deck%n, error); if (allocated(error)) return
    deck%phi_start = phi_start
    deck%dphi = dphi
    deck%phi_deg = [(phi_start + real(k - 1, wp) * dphi, k=1, deck%n)]

    ! load, either follower
    call per_step(ctx, "f2", f2, deck%n, .true., 0.0_wp, deck%f2, deck%given(2), error)
    if (allocated(error)) return

    if (deck%follower == follower_translating) then
      call require_rule(ctx, "f_cam", .not. is_set(f_cam), "only for follower = 'flat' "// &
        "(a knife/roller follower has no sliding friction at the cam)", error)
      if (allocated(error)) return
      call require_rule(ctx, "omega_dir", .not. is_set(omega_dir), "only for follower = 'flat'", error)
      if (allocated(error)) return
      call require_rule(ctx, "ds_dphi", .not. is_set(ds_dphi(1)), "only for follower = 'flat' "// &
        "(a translating follower takes the pressure angle theta)", error)
      if (allocated(error)) return
      call per_step(ctx, "theta", theta, deck%n, .true., 0.0_wp, deck%theta_deg, deck%given(1), error)
      if (allocated(error)) return
      do k = 1, deck%n
        if (.not. abs(deck%theta_deg(k)) < 90.0_wp) then
          call deck_error(ctx, "theta("//int_str(k)//")", "must be in (-90, 90) deg (got "// &
            real_str(deck%theta_deg(k))//")", error)
          return
        end if
      end do
      call per_step(ctx, "vdir", vdir, deck%n, .false., 1.0_wp, deck%vdir, deck%given(3), error)
      if (allocated(error)) return
      do k = 1, deck%n
        if (deck%vdir(k) /= 1.0_wp .and. deck%vdir(k) /= -1.0_wp .and. deck%vdir(k) /= 0.0_wp) then
          call deck_error(ctx, "vdir("//int_str(k)//")", "must be +1 (rise), -1 (return) or 0 (at rest) (got "// &
            real_str(deck%vdir(k))//")", error)
          return
        end if
      end do
      allocate (deck%ds_dphi(deck%n), deck%x_b(deck%n), source=0.0_wp)
      deck%mu_cam = 0.0_wp
    else
      call require_rule(ctx, "theta", .not. is_set(theta(1)), "not for follower = 'flat' "// &
        "(its pressure angle is 0; give ds_dphi)", error)
      if (allocated(error)) return
      call require_rule(ctx, "vdir", .not. is_set(vdir(1)), "not for follower = 'flat' "// &
        "(the sign of ds_dphi gives rise or return)", error)
      if (allocated(error)) return
      f_cam = optional_default(f_cam, 0.0_wp)
      call require_nonnegative(ctx, "f_cam", f_cam, error); if (allocated(error)) return
      omega_dir = optional_default(omega_dir, 1.0_wp)
      call require_set(ctx, "omega_dir", omega_dir, error); if (allocated(error)) return
      call require_rule(ctx, "omega_dir", omega_dir == 1.0_wp .or. omega_dir == -1.0_wp, &
        "must be +1 (cam turns CCW) or -1 (CW) (got "//real_str(omega_dir)//")", error)
      if (allocated(error)) return
      call per_step(ctx, "ds_dphi", ds_dphi, deck%n, .true., 0.0_wp, deck%ds_dphi, deck%given(4), error)
      if (allocated(error)) return
      deck%f_cam = f_cam
      deck%omega_dir = omega_dir
      deck%mu_cam = -omega_dir * f_cam
      allocate (deck%theta_deg(deck%n), source=0.0_wp)
      deck%x_b = omega_dir * deck%ds_dphi
      deck%vdir = sign(1.0_wp, deck%ds_dphi)
      where (deck%ds_dphi == 0.0_wp) deck%vdir = 0.0_wp
    end if
  end subroutine read_cam_deck

  !> A per-step array: n values, or one value for all steps; `required` or else `default`.
  subroutine per_step(ctx, name, values, n, required, default, out, given, error)
    type(deck_context_t), intent(in) :: ctx
    character(*), intent(in) :: name
    real(wp), intent(in) :: values(:)
    integer, intent(in) :: n
    logical, intent(in) :: required
    real(wp), intent(in) :: default
    real(wp), allocatable, intent(out) :: out(:)
    !> How many values the deck gave (0, 1 or n).
    integer, intent(out) :: given
    type(error_t), allocatable, intent(out) :: error
    call count_values(ctx, name, values, given, error)
    if (allocated(error)) return
    if (given == 0) then
      if (required) then
        call deck_error(ctx, name, "missing: give one value per step ("//int_str(n)//") or one for all", error)
        return
      end if
      allocate (out(n), source=default)
    else if (given == 1) then
      allocate (out(n), source=values(1))
    else if (given == n) then
      out = values(1:n)
    else
      call deck_error(ctx, name, "expected "//int_str(n)//" values (one per step) or 1 (the same for all), got "// &
        int_str(given), error)
    end if
  end subroutine per_step

end module kinetostat_cam_deck
