!> Cam mechanisms (manual section 7): a translating follower 2 in a guide of the frame 3,
!> driven by the cam 1. The guide is a bearing of length l between its ends C (near the
!> cam) and D; the contact point B lies an overhang a = l_over before C. Sliding friction f
!> at both guide ends; for a flat-faced follower also friction f_cam at the cam.
!> Frame: origin C, y along the follower axis away from the cam (C -> D), x across it so
!> that a positive pressure angle gives the cam force a +x component. B = (x_B, -a),
!> D = (0, l). Forces N, lengths m.
module kinetostat_cam
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_vec2, only: cross
  use kinetostat_selfcheck, only: equilibrium_residual, link_balance
  use kinetostat_lapack, only: solve_dense
  implicit none
  private
  public :: cam_params_t, cam_step_t, cam_step, cam_critical_angle, jam_tolerance, kf_limit

  !> Guide denominator at or below which the follower is self-locking (K_F >= 1e9).
  real(wp), parameter :: jam_tolerance = 1.0e-9_wp
  !> Reshetov's limit of the force-increase factor K_F.
  real(wp), parameter :: kf_limit = 2.0_wp

  !> Guide geometry and friction.
  type :: cam_params_t
    !> Guide length C-D, m.
    real(wp) :: l = 0.0_wp
    !> Overhang: contact point B to the near guide end C, along the axis, m.
    real(wp) :: a = 0.0_wp
    !> Sliding friction coefficient in the guide.
    real(wp) :: f = 0.0_wp
  end type cam_params_t

  !> Results of one cam angle.
  type :: cam_step_t
    !> Normal contact force at B (cam on follower), N; 0 when jammed or contact lost.
    real(wp) :: n = 0.0_wp
    !> Cam on follower at B, normal + friction, N.
    real(wp) :: f21(2) = 0.0_wp
    !> Guide end C on follower (lateral reaction + friction), N.
    real(wp) :: f23c(2) = 0.0_wp
    !> Guide end D on follower, N.
    real(wp) :: f23d(2) = 0.0_wp
    !> Force-increase factor K_F = |F21| / F2.
    real(wp) :: kf = 0.0_wp
    !> Guide denominator: K_F = |c| / denom; <= jam_tolerance means self-locking.
    real(wp) :: denom = 0.0_wp
    !> K_F > 2 (Reshetov's limit exceeded; also set when jammed).
    logical :: kf_over = .false.
    !> Self-locking: no finite contact force moves the follower.
    logical :: jammed = .false.
    !> F2 <= 0: the load does not hold the follower on the cam.
    logical :: lost = .false.
    !> Relative equilibrium residual of the follower.
    real(wp) :: residual = 0.0_wp
    !> Relative mismatch of N from the 3x3 linear solve against the closed form.
    real(wp) :: mismatch = 0.0_wp
  end type cam_step_t

contains

  !> Critical pressure angle (rad) of a knife/roller follower on the rise:
  !> tan(theta_cr) = l / (f*(l + 2a)); pi/2 without friction.
  pure real(wp) function cam_critical_angle(p)
    !> Guide data.
    type(cam_params_t), intent(in) :: p
    cam_critical_angle = atan2(p%l, p%f * (p%l + 2.0_wp * p%a))
  end function cam_critical_angle

  !> Statics of the follower at one cam angle.
  !> theta: pressure angle (rad; 0 for the flat face); x_b: contact offset from the axis (m);
  !> mu_cam: signed cam friction (+x along the face when > 0; 0 for a roller/knife);
  !> f2: load along -y (N, > 0 presses the follower onto the cam); vdir: +1 follower moving
  !> away from the cam (rise), -1 towards it (return), 0 at rest (no guide friction).
  pure function cam_step(p, theta, x_b, mu_cam, f2, vdir) result(s)
    !> Guide data.
    type(cam_params_t), intent(in) :: p
    !> Pressure angle, rad.
    real(wp), intent(in) :: theta
    !> x of the contact point B, m.
    real(wp), intent(in) :: x_b
    !> Signed friction coefficient at the cam (along +x on the follower).
    real(wp), intent(in) :: mu_cam
    !> Load on the follower, N, along -y.
    real(wp), intent(in) :: f2
    !> Direction of the follower's motion: +1, -1 or 0.
    real(wp), intent(in) :: vdir
    type(cam_step_t) :: s
    real(wp) :: c(2), arm, rc, rd, b(2), d(2), mat(3, 3), x(3), rhs(3), sc, sd
    type(error_t), allocatable :: error

    s%lost = .not. f2 > 0.0_wp
    ! direction of the cam force per unit normal force: normal (sin, cos) + mu * tangent (cos, -sin)
    c = [sin(theta) + mu_cam * cos(theta), cos(theta) - mu_cam * sin(theta)]
    b = [x_b, -p%a]
    d = [0.0_wp, p%l]
    ! moment of the unit cam force about C, and the lateral reactions per unit N
    arm = cross(b, c)
    rd = arm / p%l
    rc = -c(1) - rd
    s%denom = c(2) - vdir * p%f * (abs(rc) + abs(rd))
    if (s%lost) return
    if (s%denom <= jam_tolerance) then
      s%jammed = .true.
      s%kf_over = .true.
      return
    end if
    s%n = f2 / s%denom
    s%f21 = s%n * c
    s%f23c = s%n * [rc, -vdir * p%f * abs(rc)]
    s%f23d = s%n * [rd, -vdir * p%f * abs(rd)]
    s%kf = hypot(c(1), c(2)) / s%denom
    s%kf_over = s%kf > kf_limit
    s%residual = equilibrium_residual([link_balance(reshape([0.0_wp, 0.0_wp, b, d, d], [2, 4]), &
                                      reshape([s%f23c, s%f21, s%f23d, 0.0_wp, -f2], [2, 4]), [real(wp) ::])])

    ! independent check: the same equilibrium as a 3x3 linear system in (N, R_C, R_D) with the
    ! friction senses of the closed form: x-forces, y-forces, moments about C
    sc = sign(1.0_wp, rc)
    sd = sign(1.0_wp, rd)
    if (rc == 0.0_wp) sc = 0.0_wp
    if (rd == 0.0_wp) sd = 0.0_wp
    mat(1, :) = [c(1), 1.0_wp, 1.0_wp]
    mat(2, :) = [c(2), -vdir * p%f * sc, -vdir * p%f * sd]
    mat(3, :) = [arm, 0.0_wp, -p%l]
    rhs = [0.0_wp, f2, 0.0_wp]
    call solve_dense(mat, rhs, x, error)
    if (allocated(error)) then
      s%mismatch = 1.0_wp
    else
      s%mismatch = abs(x(1) - s%n) / s%n
    end if
  end function cam_step

end module kinetostat_cam
