!> Machine dynamics over one cycle of the input link (pure kernel, no I/O): from the reduced
!> moment of inertia J_red(phi), its derivative dJ_red/dphi and the reduced moment of the
!> external loads M_red(phi) (given by a mechanism at any input angle through a
!> `reduced_source_t`), the steady cycle: the constant driving moment M_d of zero net work,
!> the change of kinetic energy dT(phi), the flywheel J_fw for a coefficient of speed
!> fluctuation delta (exact, and Merzalov's textbook estimate), and the true law of motion
!> omega1(phi), eps1(phi), t(phi) from the energy equation
!>   1/2 (J_fw + J_red(phi)) omega^2 = E0 + dT(phi),   dT(phi) = int_phi0^phi (M_d + M_red) dphi,
!>   eps = (M_d + M_red - 1/2 dJ_red omega^2) / (J_fw + J_red).
!> dT is integrated by 8-point Gauss-Legendre on panels of at most `panel_max` with every load
!> switch a panel bound, so it does not depend on the output step; omega's extremes are found
!> between the panel bounds (where eps = 0, by bisection in the panels next to the extreme
!> bound) and at the bounds themselves (a load switch, where omega has a kink).
module kinetostat_dynamics
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, pi, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_input, exit_geometry, out_of_memory
  use kinetostat_text, only: real_str, int_str
  implicit none
  private
  public :: reduced_t, reduced_source_t, cycle_t, motion_t
  public :: dynamics_none, dynamics_reduced, dynamics_steady, dynamics_given
  public :: cycle_setup, cycle_steady, cycle_given, motion_at, motion_from, cycle_dT, drive_at

  !> Dynamics mode: none (the input's motion as the deck gives it).
  integer, parameter :: dynamics_none = 0
  !> Dynamics mode: only the reduced quantities, motion as given.
  integer, parameter :: dynamics_reduced = 1
  !> Dynamics mode: steady cycle, the flywheel found for the deck's delta.
  integer, parameter :: dynamics_steady = 2
  !> Dynamics mode: steady cycle with the deck's flywheel; delta found.
  integer, parameter :: dynamics_given = 3

  !> Largest kinetic energy of the cycle, (J_red + j_flywheel) omega^2 / 2, J: beyond it the
  !> squares and sums of the speed law leave the range of the arithmetic.
  real(wp), parameter :: energy_limit = 1.0e300_wp
  !> The flywheel found must give back the delta asked to this relative accuracy (beyond it,
  !> delta is below what the speed's arithmetic resolves).
  real(wp), parameter :: delta_accuracy = 1.0e-6_wp

  !> Largest quadrature panel, rad (1 deg).
  real(wp), parameter :: panel_max = pi / 180.0_wp
  !> Gauss-Legendre abscissae on [-1, 1] (8 points, positive half).
  real(wp), parameter :: gl_x(4) = [0.1834346424956498_wp, 0.5255324099163290_wp, &
    0.7966664774136267_wp, 0.9602898564975363_wp]
  !> Gauss-Legendre weights (8 points, positive half).
  real(wp), parameter :: gl_w(4) = [0.3626837833783620_wp, 0.3137066458778873_wp, &
    0.2223810344533745_wp, 0.1012285362903763_wp]
  !> The 8 Gauss-Legendre abscissae in increasing order.
  real(wp), parameter :: gl_xi(8) = [-gl_x(4), -gl_x(3), -gl_x(2), -gl_x(1), gl_x(1), gl_x(2), gl_x(3), gl_x(4)]
  !> Their weights.
  real(wp), parameter :: gl_wi(8) = [gl_w(4), gl_w(3), gl_w(2), gl_w(1), gl_w(1), gl_w(2), gl_w(3), gl_w(4)]

  !> Reduced quantities at one input angle (to the input link, per unit input speed).
  type :: reduced_t
    !> J_red of the moving links, kg*m^2 (without j_rotor).
    real(wp) :: j = 0.0_wp
    !> dJ_red / dphi, kg*m^2/rad.
    real(wp) :: dj = 0.0_wp
    !> M_red of the external loads and gravity, N*m.
    real(wp) :: m = 0.0_wp
    !> False at a dead position (transfer functions undetermined).
    logical :: ok = .true.
  end type reduced_t

  !> What a mechanism gives: the reduced quantities at any input angle.
  type, abstract :: reduced_source_t
  contains
    !> Reduced quantities at input angle phi (rad).
    procedure(reduced_at_i), deferred :: at
    !> Why the reduced quantities are undefined at phi (the mechanism's own message: the
    !> group that cannot be assembled, its lengths), "" when the mechanism gives none.
    procedure :: failure => no_failure_detail
  end type reduced_source_t

  abstract interface
    pure function reduced_at_i(self, phi) result(red)
      import :: reduced_source_t, reduced_t, wp
      implicit none
      class(reduced_source_t), intent(in) :: self
      !> Input angle, rad.
      real(wp), intent(in) :: phi
      type(reduced_t) :: red
    end function reduced_at_i
  end interface

  !> The steady cycle of a machine.
  type :: cycle_t
    !> First input angle of the cycle, rad; the cycle is phi0 .. phi0 + span.
    real(wp) :: phi0 = 0.0_wp
    !> Length of the cycle, rad: 2 pi (one turn) or 4 pi (two turns: a four-stroke engine).
    real(wp) :: span = 2.0_wp * pi
    !> Panel bounds, rad (0 .. np).
    real(wp), allocatable :: node(:)
    !> dT at the panel bounds, J.
    real(wp), allocatable :: dt(:)
    !> J_red (with j_rotor) at the panel bounds, kg*m^2.
    real(wp), allocatable :: j(:)
    !> Time at the panel bounds, s.
    real(wp), allocatable :: time(:)
    !> M_red at the 8 Gauss-Legendre points of each panel (8, np), N*m.
    real(wp), allocatable :: m_gl(:, :)
    !> 1/omega at the 8 Gauss-Legendre points of each panel (8, np), s/rad.
    real(wp), allocatable :: r_gl(:, :)
    !> The Lagrange polynomials through the 8 points on [-1, 1], coefficients of xi^0..xi^7:
    !> an integral from a panel's start to any angle inside it is that of the interpolant
    !> through the panel's samples (exact for the whole panel: the Gauss-Legendre sum).
    real(wp) :: basis(8, 8) = 0.0_wp
    !> Constant moment of inertia of the rotor and gear train reduced to the input, kg*m^2.
    real(wp) :: j_rotor = 0.0_wp
    !> The constant part of the links' J_red (the input link's own inertia about its pivot),
    !> kg*m^2: with j_rotor and the flywheel Merzalov's first group.
    real(wp) :: j_links_constant = 0.0_wp
    !> Mean speed (omega_max + omega_min)/2, rad/s.
    real(wp) :: omega_mean = 0.0_wp
    !> Driving moment, N*m (constant, zero net work over the cycle; 0 with a driving-moment
    !> table: drive_at; its mean is then -load_work/span).
    real(wp) :: m_d = 0.0_wp
    !> A driving-moment table: its angles, rad (increasing, within one cycle from the first),
    !> and its moments scaled to zero net work, N*m (not allocated: M_d constant).
    real(wp), allocatable :: drive_phi(:), drive_m(:)
    !> The factor the table's values were scaled by.
    real(wp) :: drive_scale = 1.0_wp
    !> Flywheel, kg*m^2.
    real(wp) :: j_flywheel = 0.0_wp
    !> Merzalov's estimate of the flywheel, kg*m^2.
    real(wp) :: j_flywheel_textbook = 0.0_wp
    !> Kinetic energy at phi0, J.
    real(wp) :: e0 = 0.0_wp
    !> Coefficient of speed fluctuation reached.
    real(wp) :: delta = 0.0_wp
    !> Largest and smallest speed, rad/s, and their angles, rad.
    real(wp) :: omega_max = 0.0_wp, phi_max = 0.0_wp, omega_min = 0.0_wp, phi_min = 0.0_wp
    !> Period of the cycle, s.
    real(wp) :: period = 0.0_wp
    !> Work of the loads over the cycle (= -span M_d), J.
    real(wp) :: load_work = 0.0_wp
    !> The flywheel drawn as a disc: its material's density, kg/m^3, and its width over its
    !> diameter, b/D.
    real(wp) :: flywheel_density = 7800.0_wp, flywheel_width_ratio = 0.2_wp
  end type cycle_t

  !> The motion and the reduced quantities at one input angle.
  type :: motion_t
    !> Input speed, rad/s.
    real(wp) :: omega = 0.0_wp
    !> Input acceleration, rad/s^2.
    real(wp) :: eps = 0.0_wp
    !> Time from phi0, s.
    real(wp) :: t = 0.0_wp
    !> Change of kinetic energy from phi0, J.
    real(wp) :: dt = 0.0_wp
    !> J_red with j_rotor, kg*m^2.
    real(wp) :: j = 0.0_wp
    !> dJ_red/dphi, kg*m^2/rad.
    real(wp) :: dj = 0.0_wp
    !> M_red, N*m.
    real(wp) :: m = 0.0_wp
    !> The driving moment M_d at the angle, N*m.
    real(wp) :: md = 0.0_wp
    !> The work of the driving moment from phi0, int M_d dphi, J (dT - a_md is the loads').
    real(wp) :: a_md = 0.0_wp
    !> Merzalov's T_I = dT - (J_red - J_c) omega_m^2/2, J_c = j_rotor + the links' constant
    !> part (the kinetic energy of the first group less its value at phi0), J.
    real(wp) :: t_i = 0.0_wp
  end type motion_t

contains

  !> The panels of the cycle phi0 .. phi0 + span (load switches `breaks`, rad, as bounds),
  !> J_red and the work of M_red at their bounds, and M_d of zero net work; `where` names the
  !> deck in messages.
  pure subroutine cycle_setup(source, phi0, breaks, j_rotor, omega_mean, where, cycle, error, drive_phi, drive_value, &
                              span)
    !> The mechanism's reduced quantities.
    class(reduced_source_t), intent(in) :: source
    !> First input angle, rad.
    real(wp), intent(in) :: phi0
    !> Input angles where a load switches, rad (any turn; taken modulo 2 pi, in every turn of
    !> the cycle).
    real(wp), intent(in) :: breaks(:)
    !> Rotor's moment of inertia reduced to the input, kg*m^2.
    real(wp), intent(in) :: j_rotor
    !> Mean speed, rad/s (> 0).
    real(wp), intent(in) :: omega_mean
    !> "deck.nml: &group" for messages.
    character(*), intent(in) :: where
    type(cycle_t), intent(out) :: cycle
    type(error_t), allocatable, intent(out) :: error
    !> A driving-moment table (optional, both or neither): angles, rad (strictly increasing,
    !> last - first < span; periodic over the cycle, linear between the points), and the
    !> moments in any scale: they are scaled so that the cycle does zero net work.
    real(wp), intent(in), optional :: drive_phi(:), drive_value(:)
    !> Length of the cycle, rad: 2 pi (default, one turn) or 4 pi (two turns).
    real(wp), intent(in), optional :: span
    real(wp), allocatable :: bounds(:), all_breaks(:)
    real(wp) :: b, w, piece, c, h
    type(reduced_t) :: red
    integer :: i, k, np, pieces, q, stat, turn, turns

    cycle%phi0 = phi0
    if (present(span)) cycle%span = span
    turns = nint(cycle%span / (2.0_wp * pi))
    cycle%j_rotor = j_rotor
    cycle%omega_mean = omega_mean
    if (.not. (phi0 + cycle%span) - phi0 > 6.0_wp) then
      call fatal_error(error, exit_input, where//": phi_start: "//real_str(phi0 * rad_to_deg)//" deg is too large: "// &
        "the angles of a turn from there are below the resolution of the arithmetic (give the start within a turn)")
      return
    end if
    ! piece bounds: phi0, the switches inside the cycle, in each of its turns (sorted,
    ! distinct), phi0 + span
    if (present(drive_phi) .and. present(drive_value)) then
      allocate (cycle%drive_phi, source=drive_phi)
      allocate (cycle%drive_m, source=drive_value)
      allocate (all_breaks(size(breaks) + size(drive_phi)))
      all_breaks(size(breaks) + 1:) = drive_phi
    else
      allocate (all_breaks(size(breaks)))
    end if
    all_breaks(1:size(breaks)) = breaks
    allocate (bounds(turns * size(all_breaks) + 2))
    bounds(1) = phi0
    k = 1
    do i = 1, size(all_breaks)
      do turn = 0, turns - 1
        b = phi0 + modulo(all_breaks(i) - phi0, 2.0_wp * pi) + 2.0_wp * pi * real(turn, wp)
        if (b - phi0 <= 1.0e-12_wp .or. phi0 + cycle%span - b <= 1.0e-12_wp) cycle
        k = k + 1
        bounds(k) = b
      end do
    end do
    call sort(bounds(2:k))
    np = 1
    do i = 2, k
      if (bounds(i) - bounds(np) <= 1.0e-12_wp) cycle
      np = np + 1
      bounds(np) = bounds(i)
    end do
    np = np + 1
    bounds(np) = phi0 + cycle%span
    bounds = bounds(1:np)
    ! panels
    np = 0
    do i = 1, size(bounds) - 1
      np = np + max(1, ceiling((bounds(i + 1) - bounds(i)) / panel_max - 1.0e-9_wp))
    end do
    allocate (cycle%node(0:np), stat=stat)
    if (stat == 0) allocate (cycle%dt(0:np), stat=stat)
    if (stat == 0) allocate (cycle%j(0:np), stat=stat)
    if (stat == 0) allocate (cycle%time(0:np), stat=stat)
    if (stat == 0) allocate (cycle%m_gl(8, np), stat=stat)
    if (stat == 0) allocate (cycle%r_gl(8, np), stat=stat)
    if (stat /= 0) then
      call out_of_memory(error, "the "//int_str(np)//" panels of the cycle's quadrature", 160_int64 * np)
      error%message = where//": dynamics: "//error%message
      return
    end if
    k = 0
    cycle%node(0) = phi0
    do i = 1, size(bounds) - 1
      piece = bounds(i + 1) - bounds(i)
      pieces = max(1, ceiling(piece / panel_max - 1.0e-9_wp))
      do q = 1, pieces - 1
        k = k + 1
        cycle%node(k) = bounds(i) + piece * real(q, wp) / real(pieces, wp)
      end do
      k = k + 1
      cycle%node(k) = bounds(i + 1)
    end do
    np = k
    ! M_red at each panel's Gauss-Legendre points; its work at the bounds (stored in dt until
    ! M_d is known)
    cycle%basis = lagrange_basis()
    cycle%dt(0) = 0.0_wp
    do k = 1, np
      c = 0.5_wp * (cycle%node(k - 1) + cycle%node(k))
      h = 0.5_wp * (cycle%node(k) - cycle%node(k - 1))
      do q = 1, 8
        red = source%at(c + h * gl_xi(q))
        if (.not. red%ok) then
          call dead_error(source, c + h * gl_xi(q), where, error)
          return
        end if
        cycle%m_gl(q, k) = red%m
      end do
      w = h * sum(gl_wi * cycle%m_gl(:, k))
      cycle%dt(k) = cycle%dt(k - 1) + w
    end do
    do k = 0, np
      red = source%at(cycle%node(k))
      if (.not. red%ok) then
        call dead_error(source, cycle%node(k), where, error)
        return
      end if
      cycle%j(k) = red%j + j_rotor
    end do
    cycle%load_work = cycle%dt(np)
    cycle%m_d = -cycle%dt(np) / cycle%span
    if (allocated(cycle%drive_m)) then
      ! the table's shape, scaled to zero net work: its work over the panels (linear in each)
      w = 0.0_wp
      c = 0.0_wp
      do k = 1, np
        w = w + 0.5_wp * (cycle%node(k) - cycle%node(k - 1)) * &
            (drive_at(cycle, cycle%node(k - 1)) + drive_at(cycle, cycle%node(k)))
        c = c + 0.5_wp * (cycle%node(k) - cycle%node(k - 1)) * &
            (abs(drive_at(cycle, cycle%node(k - 1))) + abs(drive_at(cycle, cycle%node(k))))
      end do
      if (abs(w) <= 1.0e-12_wp * c) then
        call fatal_error(error, exit_input, where//": md_table: the driving-moment table does no net work "// &
          "over the cycle: it cannot be scaled to balance the loads' work "//real_str(cycle%load_work)//" J")
        return
      end if
      if (.not. -cycle%load_work / w > 0.0_wp) then
        call fatal_error(error, exit_input, where//": md_table: the table's work over the cycle ("// &
          real_str(w)//" J as given) has the sign of the loads' ("//real_str(cycle%load_work)// &
          " J): no positive scale makes the net work zero (a motor's table drives where the loads consume)")
        return
      end if
      cycle%drive_scale = -cycle%load_work / w
      cycle%drive_m = cycle%drive_m * cycle%drive_scale
      ! dT = work of M_red (so far) + the table's, cumulated over the panels; M_d constant = 0
      c = 0.0_wp
      do k = 1, np
        c = c + 0.5_wp * (cycle%node(k) - cycle%node(k - 1)) * &
            (drive_at(cycle, cycle%node(k - 1)) + drive_at(cycle, cycle%node(k)))
        cycle%dt(k) = cycle%dt(k) + c
      end do
      cycle%m_d = 0.0_wp
      cycle%dt(np) = 0.0_wp
      return
    end if
    do k = 0, np
      cycle%dt(k) = cycle%dt(k) + cycle%m_d * (cycle%node(k) - phi0)
    end do
    cycle%dt(np) = 0.0_wp
    ! M_d < 0 is an engine's case (the loads drive: M_d is the consumer's constant moment);
    ! a machine that M_d cannot carry through the cycle stops: cycle_given's and
    ! cycle_steady's errors
  end subroutine cycle_setup

  !> The steady cycle with the flywheel that gives the coefficient of speed fluctuation
  !> `delta` (after cycle_setup): J_fw by a root find on delta(J_fw), each value from the
  !> speed law whose (omega_max + omega_min)/2 is the mean speed. A machine whose J_red does
  !> not change (every link massless, or only the input link's own inertia) has the flywheel
  !> in closed form: J_fw = dE_max / (delta omega_m^2) - J_red.
  pure subroutine cycle_steady(source, delta, where, cycle, error)
    class(reduced_source_t), intent(in) :: source
    !> Coefficient of speed fluctuation asked for (0 < delta < 1).
    real(wp), intent(in) :: delta
    character(*), intent(in) :: where
    type(cycle_t), intent(inout) :: cycle
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: x_lo, x_hi, d_lo, d_hi, x, d, j_ref, j_tb, j_fw
    integer :: it, side
    logical :: ok

    call energy_in_range(cycle, 0.0_wp, where, error)
    if (allocated(error)) return
    ! the flywheel holds about dE/delta of kinetic energy ((J_fw + J) omega_m^2 = dE/delta)
    if (.not. (maxval(cycle%dt) - minval(cycle%dt)) / delta <= energy_limit) then
      call fatal_error(error, exit_input, where//": delta: with the loads' work over the cycle changing the kinetic "// &
        "energy by "//real_str(maxval(cycle%dt) - minval(cycle%dt))//" J, the flywheel for delta = "//real_str(delta)// &
        " would hold about "//real_str((maxval(cycle%dt) - minval(cycle%dt)) / delta)//" J: out of the range of "// &
        "the arithmetic (above 1e300 J); give a larger delta or smaller loads")
      return
    end if
    call textbook(cycle, delta, j_tb)
    cycle%j_flywheel_textbook = j_tb
    if (maxval(cycle%j) == minval(cycle%j)) then
      call constant_inertia_flywheel(j_fw, error)
      if (allocated(error)) return
      call speed_law(source, cycle, j_fw, d, ok)
      call check_found(ok, d, error)
      if (allocated(error)) return
      call finish_time(source, cycle)
      return
    end if
    ! the bare machine (no flywheel)
    call speed_law(source, cycle, 0.0_wp, d, ok)
    if (ok) then
      if (d <= delta) then
        call no_flywheel_needed(d, error)
        return
      end if
    end if
    ! root find in x = 1/(J_fw + J_ref), where delta is nearly linear
    j_ref = maxval(cycle%j)
    x_lo = 1.0_wp / j_ref
    ! upper end: a flywheel large enough that delta is below the asked one
    x_hi = x_lo
    do it = 1, 200
      x_hi = x_hi * 0.25_wp
      call speed_law(source, cycle, 1.0_wp / x_hi - j_ref, d_hi, ok)
      if (ok .and. d_hi < delta) exit
    end do
    if (.not. (ok .and. d_hi < delta)) then
      call fatal_error(error, exit_input, where//": delta: no flywheel up to "//real_str(1.0_wp / x_hi)// &
        " kg*m^2 brings the speed's fluctuation down to delta = "//real_str(delta)// &
        " (below what the arithmetic of the speed resolves); give a larger delta")
      return
    end if
    x_lo = x_hi * 4.0_wp
    call speed_law(source, cycle, 1.0_wp / x_lo - j_ref, d_lo, ok)
    if (.not. ok) d_lo = 2.0_wp
    ! Illinois regula falsi on d(x) - delta over [x_hi, x_lo]
    side = 0
    do it = 1, 200
      x = x_hi + (delta - d_hi) * (x_lo - x_hi) / (d_lo - d_hi)
      if (.not. (x > min(x_hi, x_lo) .and. x < max(x_hi, x_lo))) x = 0.5_wp * (x_hi + x_lo)
      call speed_law(source, cycle, 1.0_wp / x - j_ref, d, ok)
      if (.not. ok) d = 2.0_wp
      if (abs(d - delta) <= 1.0e-14_wp * delta .or. abs(x_lo - x_hi) <= 1.0e-15_wp * x) exit
      if (d > delta) then
        x_lo = x
        d_lo = d
        if (side == -1) d_hi = delta + 0.5_wp * (d_hi - delta)
        side = -1
      else
        x_hi = x
        d_hi = d
        if (side == 1) d_lo = delta + 0.5_wp * (d_lo - delta)
        side = 1
      end if
    end do
    call speed_law(source, cycle, 1.0_wp / x - j_ref, d, ok)
    call check_found(ok, d, error)
    if (allocated(error)) return
    call finish_time(source, cycle)
  contains
    !> The speed law with the flywheel found must exist and give back delta.
    pure subroutine check_found(ok, d, error)
      logical, intent(in) :: ok
      real(wp), intent(in) :: d
      type(error_t), allocatable, intent(out) :: error
      if (.not. ok) then
        call fatal_error(error, exit_input, where//": delta: no speed law of mean speed omega1 = "// &
          real_str(cycle%omega_mean)//" rad/s gives delta = "//real_str(delta)//" (the root find ended "// &
          "where the speed would fall to zero); give a smaller delta")
      else if (.not. abs(d - delta) <= delta_accuracy * delta) then
        call fatal_error(error, exit_input, where//": delta: "//real_str(delta)//" is below what the "// &
          "arithmetic of the speed resolves (the flywheel found, "//real_str(cycle%j_flywheel)// &
          " kg*m^2, gives delta = "//real_str(d)//"); give a larger delta")
      end if
    end subroutine check_found

    !> The machine without a flywheel already runs with delta_bare <= delta.
    pure subroutine no_flywheel_needed(delta_bare, error)
      real(wp), intent(in) :: delta_bare
      type(error_t), allocatable, intent(out) :: error
      call fatal_error(error, exit_input, where//": delta: the machine without a flywheel already runs with "// &
        "delta = "//real_str(delta_bare)//" <= "//real_str(delta)//" (j_rotor and the links suffice): no flywheel "// &
        "is needed; give a smaller delta or dynamics = 'given' with j_flywheel = 0")
    end subroutine no_flywheel_needed

    !> J_red constant (J_c): with the largest change of kinetic energy over the cycle dE,
    !> (omega_max^2 - omega_min^2) (J_fw + J_c)/2 = dE and omega_max + omega_min = 2 omega_m
    !> give J_fw + J_c = dE / (delta omega_m^2) exactly.
    pure subroutine constant_inertia_flywheel(j_fw, error)
      !> The flywheel, kg*m^2.
      real(wp), intent(out) :: j_fw
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: de, j_c
      j_c = cycle%j(0)
      de = energy_swing(source, cycle)
      j_fw = de / (delta * cycle%omega_mean**2) - j_c
      if (.not. de > 0.0_wp) then
        call fatal_error(error, exit_input, where//": delta: the kinetic energy does not change over the cycle "// &
          "(the loads' work and M_d balance at every angle): any flywheel gives delta = 0, none is needed; "// &
          "give dynamics = 'given' with j_flywheel")
      else if (j_fw <= 0.0_wp) then
        call no_flywheel_needed(de / (j_c * cycle%omega_mean**2), error)
      end if
    end subroutine constant_inertia_flywheel
  end subroutine cycle_steady

  !> The largest change of kinetic energy over the cycle, max dT - min dT, J (the extremes
  !> between the panel bounds included): from the speed law's extremes with a constant
  !> J_red, where omega^2 (J_fw + J_red)/2 - dT is the same at every angle.
  pure real(wp) function energy_swing(source, cycle) result(de)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    real(wp) :: e0, j_total, w_max, p_max, w_min, p_min
    logical :: ok
    de = maxval(cycle%dt) - minval(cycle%dt)
    if (.not. de > 0.0_wp) return
    j_total = 1.0_wp + cycle%j(0)
    e0 = -minval(cycle%dt) + 2.0_wp * de
    call extremes(source, cycle, 1.0_wp, e0, w_max, p_max, w_min, p_min, ok)
    if (ok) de = 0.5_wp * j_total * (w_max - w_min) * (w_max + w_min)
  end function energy_swing

  !> The kinetic energy of the cycle, (J_red,max + j_flywheel) omega_m^2 / 2, must stay within
  !> energy_limit; beyond it, the value that puts it there is named: the mean speed, the
  !> flywheel, the rotor, or the links' inertia (J_red).
  pure subroutine energy_in_range(cycle, j_flywheel, where, error)
    type(cycle_t), intent(in) :: cycle
    !> Flywheel, kg*m^2 (0 with dynamics = 'steady': found later).
    real(wp), intent(in) :: j_flywheel
    character(*), intent(in) :: where
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: j_total, j_links, w2
    character(len=:), allocatable :: why
    j_total = maxval(cycle%j) + j_flywheel
    j_links = maxval(cycle%j) - cycle%j_rotor
    w2 = cycle%omega_mean**2
    if (.not. maxval(abs(cycle%dt)) <= energy_limit) then
      call fatal_error(error, exit_input, where//": dynamics: the loads' work over the cycle (the change of kinetic "// &
        "energy dT, up to "//finite_text(maxval(abs(cycle%dt)))//" J) is out of the range of the arithmetic (above "// &
        "1e300 J): the loads' magnitudes are too large")
      return
    end if
    if (0.5_wp * j_total * w2 <= energy_limit) return
    why = ": the kinetic energy (J_red + j_rotor + j_flywheel)*omega1^2/2 at the mean speed omega1 = "// &
      finite_text(cycle%omega_mean)//" rad/s with J_red + j_rotor + j_flywheel up to "//finite_text(j_total)// &
      " kg*m^2 is out of the range of the arithmetic (above 1e300 J)"
    if (.not. w2 <= energy_limit .or. log10(max(w2, tiny(1.0_wp))) >= log10(max(j_total, tiny(1.0_wp)))) then
      call fatal_error(error, exit_input, where//": omega1"//why)
    else if (j_flywheel >= cycle%j_rotor .and. j_flywheel >= j_links) then
      call fatal_error(error, exit_input, where//": j_flywheel"//why)
    else if (cycle%j_rotor >= j_links) then
      call fatal_error(error, exit_input, where//": j_rotor"//why)
    else
      call fatal_error(error, exit_input, where//": J_red (the links' masses and moments of inertia)"//why)
    end if
  contains
    !> A figure of a message: its value, or words for one beyond the largest real.
    pure function finite_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      if (abs(x) <= huge(x)) then
        text = real_str(x)
      else
        text = "more than the largest real"
      end if
    end function finite_text
  end subroutine energy_in_range

  !> The steady cycle with the flywheel `j_flywheel` (after cycle_setup): the speed law of
  !> mean speed omega_mean and the delta it gives.
  pure subroutine cycle_given(source, j_flywheel, where, cycle, error)
    class(reduced_source_t), intent(in) :: source
    !> Flywheel, kg*m^2 (>= 0).
    real(wp), intent(in) :: j_flywheel
    character(*), intent(in) :: where
    type(cycle_t), intent(inout) :: cycle
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: d, j_tb
    logical :: ok
    call energy_in_range(cycle, j_flywheel, where, error)
    if (allocated(error)) return
    if (.not. j_flywheel + maxval(cycle%j) > 0.0_wp) then
      call fatal_error(error, exit_input, where//": j_flywheel: the machine has no inertia (every link massless, "// &
        "j_rotor = 0) and j_flywheel = 0: its speed is undefined; give a flywheel")
      return
    end if
    call speed_law(source, cycle, j_flywheel, d, ok)
    if (.not. ok) then
      call fatal_error(error, exit_input, where//": j_flywheel: with j_flywheel = "//real_str(j_flywheel)// &
        " kg*m^2 the speed would fall to zero within the cycle at the mean speed omega1 = "// &
        real_str(cycle%omega_mean)//" rad/s: M_d cannot carry the machine through; give a larger flywheel")
      return
    end if
    if (d > 0.0_wp) then
      call textbook(cycle, d, j_tb)
      cycle%j_flywheel_textbook = j_tb
    end if
    call finish_time(source, cycle)
  end subroutine cycle_given

  !> Merzalov's estimate for `delta`: with J_c = j_rotor + the links' constant part (the first
  !> group besides the flywheel), T_I = dT - (J_red - J_c) omega_m^2/2 over the panel bounds,
  !> J_I = (max T_I - min T_I)/(delta omega_m^2), J_fw = J_I - J_c.
  pure subroutine textbook(cycle, delta, j_fw)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: delta
    real(wp), intent(out) :: j_fw
    real(wp) :: t1(size(cycle%dt)), j_c
    j_c = cycle%j_rotor + cycle%j_links_constant
    t1 = cycle%dt - (cycle%j - j_c) * cycle%omega_mean**2 / 2.0_wp
    j_fw = (maxval(t1) - minval(t1)) / (delta * cycle%omega_mean**2) - j_c
  end subroutine textbook

  !> The speed law with flywheel `j_fw`: E0 such that (omega_max + omega_min)/2 = omega_mean,
  !> the extremes and `delta`; `ok` false when no such law keeps omega > 0. (omega_max +
  !> omega_min)/2 is concave and increasing in E0: Newton's method from the bracket's upper
  !> end (where omega >= omega_m everywhere) overshoots once, then climbs to the root from
  !> below; a step that leaves the bracket [E0 where the speed reaches zero, upper end], or an
  !> E0 where it does, is replaced by bisection.
  pure subroutine speed_law(source, cycle, j_fw, delta, ok)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(inout) :: cycle
    !> Flywheel, kg*m^2.
    real(wp), intent(in) :: j_fw
    real(wp), intent(out) :: delta
    logical, intent(out) :: ok
    real(wp) :: e0, e_lo, e_hi, e_new, f, df, w_max, w_min, p_max, p_min, wm
    integer :: it
    logical :: converged
    wm = cycle%omega_mean
    e_hi = 0.5_wp * (j_fw + maxval(cycle%j)) * wm**2 - minval(cycle%dt)
    e_lo = -minval(cycle%dt)
    e0 = e_hi
    ok = .false.
    delta = 0.0_wp
    converged = .false.
    ! at most 200 steps on e0; the extremes are evaluated once more after the last one
    do it = 1, 201
      ok = all(e0 + cycle%dt > 0.0_wp)
      if (ok) call extremes(source, cycle, j_fw, e0, w_max, p_max, w_min, p_min, ok)
      if (ok) ok = w_min > 0.0_wp
      if (.not. ok) then
        ! the speed reaches zero: E0 is too low (at the upper end there is no law at all)
        if (it == 1 .or. it == 201) return
        e_lo = e0
        e0 = 0.5_wp * (e_lo + e_hi)
        converged = .false.
        cycle
      end if
      if (converged .or. it == 201) exit
      f = 0.5_wp * (w_max + w_min) - wm
      if (f > 0.0_wp) then
        e_hi = e0
      else
        e_lo = e0
      end if
      df = 0.5_wp * (1.0_wp / ((j_fw + j_at(source, cycle, p_max)) * w_max) + &
                     1.0_wp / ((j_fw + j_at(source, cycle, p_min)) * w_min))
      e_new = e0 - f / df
      if (.not. (e_new >= e_lo .and. e_new <= e_hi)) e_new = 0.5_wp * (e_lo + e_hi)
      converged = abs(e_new - e0) <= 1.0e-15_wp * abs(e_new) .or. abs(f) <= 1.0e-15_wp * wm .or. &
        e_hi - e_lo <= 1.0e-15_wp * abs(e_new)
      e0 = e_new
    end do
    ! a law whose mean is not omega_m (the bracket closed on the speed's zero) is none
    ok = abs(0.5_wp * (w_max + w_min) - wm) <= 1.0e-10_wp * wm
    if (.not. ok) return
    cycle%j_flywheel = j_fw
    cycle%e0 = e0
    cycle%omega_max = w_max
    cycle%phi_max = p_max
    cycle%omega_min = w_min
    cycle%phi_min = p_min
    delta = (w_max - w_min) / wm
    cycle%delta = delta
  end subroutine speed_law

  !> omega's largest and smallest value over the cycle and their angles: the extreme panel
  !> bound, then the stationary point (eps = 0) in the two panels next to it.
  pure subroutine extremes(source, cycle, j_fw, e0, w_max, p_max, w_min, p_min, ok)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: j_fw, e0
    real(wp), intent(out) :: w_max, p_max, w_min, p_min
    logical, intent(out) :: ok
    real(wp) :: w(0:size(cycle%node) - 1)
    integer :: np, i
    np = size(cycle%node) - 1
    w = sqrt(2.0_wp * (e0 + cycle%dt) / (j_fw + cycle%j))
    ok = all(w > 0.0_wp)
    i = maxloc(w, 1) - 1
    call refine(i, 1.0_wp, w_max, p_max)
    i = minloc(w, 1) - 1
    call refine(i, -1.0_wp, w_min, p_min)
  contains
    !> Best of node i and the stationary points in its two panels (sense +1: max).
    pure subroutine refine(i, sense, w_best, p_best)
      integer, intent(in) :: i
      real(wp), intent(in) :: sense
      real(wp), intent(out) :: w_best, p_best
      real(wp) :: wx, px
      integer :: lo, hi
      w_best = w(i)
      p_best = cycle%node(i)
      ! panels next to node i (node 0 and node np are the same angle)
      lo = i - 1
      hi = i + 1
      if (i == 0) lo = np - 1
      if (i == np) hi = 1
      call stationary(lo, sense, wx, px)
      if (sense * (wx - w_best) > 0.0_wp) then
        w_best = wx
        p_best = px
      end if
      call stationary(hi - 1, sense, wx, px)
      if (sense * (wx - w_best) > 0.0_wp) then
        w_best = wx
        p_best = px
      end if
      if (p_best >= cycle%node(np)) p_best = p_best - cycle%span
    end subroutine refine

    !> The extreme of omega inside panel k (node k .. k+1), where eps = 0: bisection on the
    !> sign of g = (J_fw + J_red) eps = M_d + M_red - dJ_red omega^2/2, which falls through 0 at
    !> a largest omega (sense +1) and rises through 0 at a smallest (sense -1). Without such a
    !> sign change in the panel, w_best = -sense*huge (the extreme is at a bound).
    pure subroutine stationary(k, sense, w_best, p_best)
      integer, intent(in) :: k
      real(wp), intent(in) :: sense
      real(wp), intent(out) :: w_best, p_best
      real(wp) :: a, b, c, inset
      integer :: it
      w_best = -sense * huge(1.0_wp)
      p_best = cycle%node(k)
      inset = 1.0e-6_wp * (cycle%node(k + 1) - cycle%node(k))
      a = cycle%node(k) + inset
      b = cycle%node(k + 1) - inset
      if (.not. (sense * g_of(a) > 0.0_wp .and. sense * g_of(b) < 0.0_wp)) return
      do it = 1, 200
        c = 0.5_wp * (a + b)
        if (c <= a .or. c >= b) exit
        if (sense * g_of(c) > 0.0_wp) then
          a = c
        else
          b = c
        end if
      end do
      p_best = 0.5_wp * (a + b)
      w_best = omega_of(p_best)
    end subroutine stationary

    !> g = M_d + M_red - dJ_red omega^2/2 at phi.
    pure real(wp) function g_of(phi)
      real(wp), intent(in) :: phi
      type(reduced_t) :: red
      red = source%at(phi)
      g_of = drive_at(cycle, phi) + red%m - 0.5_wp * red%dj * omega_of(phi)**2
    end function g_of

    !> omega at phi inside the cycle.
    pure real(wp) function omega_of(phi)
      real(wp), intent(in) :: phi
      real(wp) :: e
      e = e0 + cycle_dT(cycle, phi)
      omega_of = sqrt(2.0_wp * max(e, 0.0_wp) / (j_fw + j_at(source, cycle, phi)))
    end function omega_of
  end subroutine extremes

  !> J_red with j_rotor at phi, kg*m^2.
  pure real(wp) function j_at(source, cycle, phi)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    type(reduced_t) :: red
    red = source%at(phi)
    j_at = red%j + cycle%j_rotor
  end function j_at

  !> dT at phi (rad, taken into the cycle), J: the panel bound's value and the integral of the
  !> interpolant through the panel's samples of M_red from there.
  pure real(wp) function cycle_dT(cycle, phi) result(dt)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    real(wp) :: x, h, wt(8)
    integer :: k
    call locate(cycle, phi, x, k)
    h = 0.5_wp * (cycle%node(k + 1) - cycle%node(k))
    wt = partial_weights(cycle, (x - cycle%node(k)) / h - 1.0_wp)
    dt = dt_inside(cycle, x, k, h, wt)
  end function cycle_dT

  !> dT at x inside panel k (node k <= x <= node k+1, half-width h) from the partial weights
  !> `wt` of the panel's samples, J.
  pure real(wp) function dt_inside(cycle, x, k, h, wt) result(dt)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: x, h, wt(8)
    integer, intent(in) :: k
    dt = cycle%dt(k) + h * sum(cycle%m_gl(:, k + 1) * wt) + &
         cycle%m_d * (x - cycle%node(k))
    ! a driving-moment table is linear inside a panel (its points are panel bounds)
    if (allocated(cycle%drive_m)) dt = dt + 0.5_wp * (x - cycle%node(k)) * &
      (drive_at(cycle, cycle%node(k)) + drive_at(cycle, x))
  end function dt_inside

  !> The driving moment at phi (rad), N*m: the constant M_d, or the scaled table, linear
  !> between its points and periodic over the cycle (continuous).
  pure real(wp) function drive_at(cycle, phi) result(md)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    real(wp) :: x, x0, x1, m0, m1
    integer :: n, i
    md = cycle%m_d
    if (.not. allocated(cycle%drive_m)) return
    n = size(cycle%drive_phi)
    if (n == 1) then
      md = cycle%drive_m(1)
      return
    end if
    x = cycle%drive_phi(1) + modulo(phi - cycle%drive_phi(1), cycle%span)
    ! the segment [phi_i, phi_i+1] holding x; past the last point, the wrap to the first + span
    i = n
    do while (i > 1)
      if (cycle%drive_phi(i) <= x) exit
      i = i - 1
    end do
    x0 = cycle%drive_phi(i)
    m0 = cycle%drive_m(i)
    if (i < n) then
      x1 = cycle%drive_phi(i + 1)
      m1 = cycle%drive_m(i + 1)
    else
      x1 = cycle%drive_phi(1) + cycle%span
      m1 = cycle%drive_m(1)
    end if
    md = m0 + (m1 - m0) * (x - x0) / (x1 - x0)
  end function drive_at

  !> The weights of the samples for the integral from -1 to s (-1 <= s <= 1) of the
  !> interpolant through the 8 Gauss-Legendre points.
  pure function partial_weights(cycle, s) result(wt)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: s
    real(wp) :: wt(8), moments(8), sp, sm
    integer :: i, j
    sp = s
    sm = -1.0_wp
    do j = 1, 8
      moments(j) = (sp - sm) / real(j, wp)
      sp = sp * s
      sm = -sm
    end do
    ! explicit loops, not matmul: its library (debug build) and inlined (release build) forms
    ! sum in different orders, and t or dT would differ in a last printed digit
    wt = 0.0_wp
    !GCC$ novector
    do j = 1, 8
      !GCC$ novector
      do i = 1, 8
        wt(i) = wt(i) + cycle%basis(i, j) * moments(j)
      end do
    end do
  end function partial_weights

  !> Coefficients of xi^0 .. xi^7 of the 8 Lagrange polynomials through gl_xi (row i: L_i).
  pure function lagrange_basis() result(basis)
    real(wp) :: basis(8, 8), poly(8)
    integer :: i, j, k, deg
    do i = 1, 8
      poly = 0.0_wp
      poly(1) = 1.0_wp
      deg = 0
      do j = 1, 8
        if (j == i) cycle
        deg = deg + 1
        do k = deg + 1, 2, -1
          poly(k) = (poly(k - 1) - gl_xi(j) * poly(k)) / (gl_xi(i) - gl_xi(j))
        end do
        poly(1) = -gl_xi(j) * poly(1) / (gl_xi(i) - gl_xi(j))
      end do
      basis(i, :) = poly
    end do
  end function lagrange_basis

  !> The panel k (node k <= x <= node k+1) of phi taken into the cycle as x.
  pure subroutine locate(cycle, phi, x, k)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    real(wp), intent(out) :: x
    integer, intent(out) :: k
    integer :: lo, hi, mid, np
    np = size(cycle%node) - 1
    x = phi
    if (x < cycle%node(0) .or. x > cycle%node(np)) x = cycle%node(0) + modulo(x - cycle%node(0), cycle%span)
    lo = 0
    hi = np
    do while (hi - lo > 1)
      mid = (lo + hi) / 2
      if (cycle%node(mid) <= x) then
        lo = mid
      else
        hi = mid
      end if
    end do
    k = lo
  end subroutine locate

  !> 1/omega at each panel's Gauss-Legendre points and the time at the panel bounds,
  !> t = int dphi/omega (8-point Gauss-Legendre per panel).
  pure subroutine finish_time(source, cycle)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(inout) :: cycle
    real(wp) :: c, h, x
    integer :: k, q
    cycle%time(0) = 0.0_wp
    do k = 1, size(cycle%node) - 1
      c = 0.5_wp * (cycle%node(k - 1) + cycle%node(k))
      h = 0.5_wp * (cycle%node(k) - cycle%node(k - 1))
      do q = 1, 8
        x = c + h * gl_xi(q)
        cycle%r_gl(q, k) = 1.0_wp / sqrt(2.0_wp * (cycle%e0 + cycle_dT(cycle, x)) / &
                                          (cycle%j_flywheel + j_at(source, cycle, x)))
      end do
      cycle%time(k) = cycle%time(k - 1) + h * sum(gl_wi * cycle%r_gl(:, k))
    end do
    cycle%period = cycle%time(size(cycle%node) - 1)
  end subroutine finish_time

  !> The motion at input angle phi (rad) of a solved cycle.
  pure function motion_at(source, cycle, phi) result(mo)
    class(reduced_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    type(motion_t) :: mo
    mo = motion_from(cycle, phi, source%at(phi))
  end function motion_at

  !> The motion at input angle phi (rad) of a solved cycle, with the reduced quantities `red`
  !> at phi already computed (source%at(phi)).
  pure function motion_from(cycle, phi, red) result(mo)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: phi
    type(reduced_t), intent(in) :: red
    type(motion_t) :: mo
    real(wp) :: x, h, wt(8)
    integer :: k
    mo%j = red%j + cycle%j_rotor
    mo%dj = red%dj
    mo%m = red%m
    ! one panel and one set of partial weights for dT and t (the same interpolation)
    call locate(cycle, phi, x, k)
    h = 0.5_wp * (cycle%node(k + 1) - cycle%node(k))
    wt = partial_weights(cycle, (x - cycle%node(k)) / h - 1.0_wp)
    mo%dt = dt_inside(cycle, x, k, h, wt)
    mo%omega = sqrt(2.0_wp * max(cycle%e0 + mo%dt, 0.0_wp) / (cycle%j_flywheel + mo%j))
    mo%md = drive_at(cycle, phi)
    mo%eps = (mo%md + mo%m - 0.5_wp * mo%dj * mo%omega**2) / (cycle%j_flywheel + mo%j)
    mo%t = cycle%time(k) + h * sum(cycle%r_gl(:, k + 1) * wt)
    mo%a_md = drive_work(cycle, x)
    mo%t_i = mo%dt - (mo%j - cycle%j_rotor - cycle%j_links_constant) * cycle%omega_mean**2 / 2.0_wp
  end function motion_from

  !> The work of the driving moment from phi0 to x (rad, phi0 <= x <= phi0 + 2 pi), J: M_d (x -
  !> phi0), or the exact integral of the table (linear between its points, periodic).
  pure real(wp) function drive_work(cycle, x) result(work)
    type(cycle_t), intent(in) :: cycle
    real(wp), intent(in) :: x
    real(wp) :: a, b, lo, hi, turn
    integer :: n, i, m
    work = cycle%m_d * (x - cycle%phi0)
    if (.not. allocated(cycle%drive_m)) return
    n = size(cycle%drive_phi)
    work = 0.0_wp
    if (n == 1) then
      work = cycle%drive_m(1) * (x - cycle%phi0)
      return
    end if
    turn = 2.0_wp * pi
    ! every segment of the table, in the turns that may overlap [phi0, x]
    do m = floor((cycle%phi0 - cycle%drive_phi(1)) / turn) - 1, floor((x - cycle%drive_phi(1)) / turn) + 1
      do i = 1, n
        a = cycle%drive_phi(i) + m * turn
        if (i < n) then
          b = cycle%drive_phi(i + 1) + m * turn
        else
          b = cycle%drive_phi(1) + (m + 1) * turn
        end if
        lo = max(a, cycle%phi0)
        hi = min(b, x)
        if (hi <= lo) cycle
        ! the table is linear on the segment and continuous: its trapezoid is exact
        work = work + 0.5_wp * (hi - lo) * (drive_at(cycle, lo) + drive_at(cycle, hi))
      end do
    end do
  end function drive_work

  !> The error of a dead position met in the cycle: the mechanism's own message (the group,
  !> its lengths) at that input angle, as a plain run names it at a step.
  pure subroutine dead_error(source, phi, where, error)
    class(reduced_source_t), intent(in) :: source
    real(wp), intent(in) :: phi
    character(*), intent(in) :: where
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: detail
    detail = source%failure(phi)
    if (len(detail) > 0) then
      call fatal_error(error, exit_geometry, where//": dynamics: the cycle at phi1 = "// &
        real_str(phi * rad_to_deg)//" deg: "//detail)
      return
    end if
    call fatal_error(error, exit_geometry, where//": dynamics: the cycle passes through a dead position (or one "// &
      "that cannot be assembled) near the input angle "//real_str(phi * rad_to_deg)// &
      " deg: the reduced quantities are undefined there")
  end subroutine dead_error

  !> No detail of a failure (a mechanism that does not say why).
  pure function no_failure_detail(self, phi) result(text)
    class(reduced_source_t), intent(in) :: self
    !> Input angle, rad.
    real(wp), intent(in) :: phi
    character(len=:), allocatable :: text
    text = ""
  end function no_failure_detail

  !> Sort ascending (heapsort: a load table may give one switch per step).
  pure subroutine sort(x)
    real(wp), intent(inout) :: x(:)
    real(wp) :: t
    integer :: n, i
    n = size(x)
    do i = n / 2, 1, -1
      call sift(x, i, n)
    end do
    do i = n, 2, -1
      t = x(1)
      x(1) = x(i)
      x(i) = t
      call sift(x, 1, i - 1)
    end do
  end subroutine sort

  !> Restore the heap below node `root` within x(1:last) (heapsort's step).
  pure subroutine sift(x, root, last)
    real(wp), intent(inout) :: x(:)
    integer, intent(in) :: root, last
    integer :: parent, child
    real(wp) :: v
    parent = root
    v = x(parent)
    do
      child = 2 * parent
      if (child > last) exit
      if (child < last) then
        if (x(child + 1) > x(child)) child = child + 1
      end if
      if (.not. x(child) > v) exit
      x(parent) = x(child)
      parent = child
    end do
    x(parent) = v
  end subroutine sift

end module kinetostat_dynamics
