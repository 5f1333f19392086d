!> What a run reduces over its rows beyond the columns' own extremes and sums (those are
!> kinetostat_summary's tally_rows, in row order): the self-check's largest figures, the
!> drive deviation of the true motion (a ratio of maxima, its numerator and denominator
!> carried apart), the peaks of the pair forces with the true motion and at constant speed,
!> a mechanism's own maxima (the linkage solver's gap), trapezoid integrals over the rows
!> (the friction works) and flag counts with their first row (a cam follower jammed). A
!> kind's `solve` notes its block's figures in a tally of the block; the run pipeline
!> merges that into the run's tally after every block (merge_tally), the one place where
!> blocks meet, so a run gives the same figures whatever its block size: maxima by max,
!> counts by addition, integrals fed with the block's points in row order (the same sums,
!> term by term, as one block gives).
!> Also the machine dynamics figures of a run (dynamics_figures_t), a typed record.
module kinetostat_run_tally
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use kinetostat_kinds, only: wp, pi
  implicit none
  private
  public :: running_max_t, ratio_of_maxima_t, force_peak_t, trapezoid_t, flag_count_t, run_tally_t, &
    dynamics_figures_t, flywheel_disc, merge_tally, column_tally_t, edge_point_t

  !> The largest value of a figure over the rows so far and the row where it is (a NaN, once
  !> seen, stays: the run's guard reports it).
  type :: running_max_t
    !> Largest value so far (0 before any).
    real(wp) :: value = 0.0_wp
    !> Row of the run (1..) where it is (0: not known).
    integer :: row = 0
    !> Whether any block gave a value.
    logical :: seen = .false.
  contains
    procedure :: note => note_max
  end type running_max_t

  !> A ratio of maxima over the run, max(numerator) / max(denominator), with both maxima
  !> carried apart (the ratio of the blocks' ratios' maximum would depend on the blocks).
  type :: ratio_of_maxima_t
    !> Largest numerator so far.
    real(wp) :: numerator = 0.0_wp
    !> Largest denominator so far.
    real(wp) :: denominator = 0.0_wp
    !> Whether any block gave one.
    logical :: seen = .false.
  contains
    procedure :: note => note_ratio
    procedure :: ratio
  end type ratio_of_maxima_t

  !> The peak of one pair force over the run with the true motion and at constant speed.
  type :: force_peak_t
    !> Force column ("F16").
    character(len=:), allocatable :: name
    !> Largest magnitude with the true motion, N.
    real(wp) :: true_motion = 0.0_wp
    !> Largest magnitude at the constant mean speed, N.
    real(wp) :: constant_speed = 0.0_wp
  end type force_peak_t

  !> The integral of y over |dx| (times `unit`) by the trapezoid rule, over the rows in order:
  !> in a block's tally the block's points (x, y), in the run's the sum so far and its last
  !> point.
  type :: trapezoid_t
    !> The integral so far (run), unit of y times unit of x times `unit`.
    real(wp) :: area = 0.0_wp
    !> Factor of |dx| (deg_to_rad: an angle in deg integrated in rad).
    real(wp) :: unit = 1.0_wp
    !> The last point fed (run).
    real(wp) :: last_x = 0.0_wp, last_y = 0.0_wp
    !> Whether a point was fed (run).
    logical :: started = .false.
    !> The block's points in row order (block).
    real(wp), allocatable :: x(:), y(:)
  contains
    procedure :: feed
  end type trapezoid_t

  !> How many rows a flag marks and the first of them.
  type :: flag_count_t
    !> Rows marked.
    integer :: count = 0
    !> First row of the run marked (0: none).
    integer :: first_row = 0
  end type flag_count_t

  !> What a run has shown so far of one column (its rows are gone once written: a run is
  !> solved and written in blocks of rows). Kept by kinetostat_summary's tally_rows.
  type :: column_tally_t
    !> Largest value so far (a later row replaces it only when larger by more than the
    !> tie allowance: equal positions such as 0 and 360 deg keep the first).
    real(wp) :: max = 0.0_wp
    !> Smallest value so far (the first one on a tie).
    real(wp) :: min = 0.0_wp
    !> Row (1..) of `max`.
    integer :: max_row = 0
    !> Row of `min`.
    integer :: min_row = 0
    !> Input coordinate at `max_row` (unit of the input column; 0 without one).
    real(wp) :: max_at = 0.0_wp
    !> Input coordinate at `min_row`.
    real(wp) :: min_at = 0.0_wp
    !> Largest value, first row on an exact tie (the coarse-step warning's peak).
    real(wp) :: peak = 0.0_wp
    !> Row of `peak`.
    integer :: peak_row = 0
    !> Input coordinate at `peak_row`.
    real(wp) :: peak_at = 0.0_wp
    !> Largest magnitude so far.
    real(wp) :: largest = 0.0_wp
    !> Sum of the values (in row order).
    real(wp) :: total = 0.0_wp
    !> Sum of (v(k) + v(k-1)) * (x(k) - x(k-1)) over the rows (twice the trapezoid integral
    !> over the input coordinate x).
    real(wp) :: area2 = 0.0_wp
    !> Value in the last row seen.
    real(wp) :: last = 0.0_wp
    !> Rows counted (a voidable column's void rows are not).
    integer :: count = 0
    !> Input coordinate covered by the trapezoids counted (both ends counted rows).
    real(wp) :: span = 0.0_wp
    !> Whether the last row seen was counted.
    logical :: last_counted = .false.
    !> `total` of the values scaled by kinetostat_summary's value_scale (2**-512), and
    !> `area2` of the values and input steps scaled by value_scale and step_scale
    !> (2**-560): the same sums in a range where they cannot overflow (|v| < 1.8e308),
    !> used when the plain ones did.
    real(wp) :: total_scaled = 0.0_wp
    !> See `total_scaled`.
    real(wp) :: area2_scaled = 0.0_wp
  end type column_tally_t

  !> The input coordinate at a row next to a load edge (for the coarse-step warning's text).
  type :: edge_point_t
    !> Row.
    integer :: row = 0
    !> Input coordinate there.
    real(wp) :: at = 0.0_wp
  end type edge_point_t

  !> The figures of a block (noted by a kind's solve) or of the run so far (merged).
  type :: run_tally_t
    !> Largest relative equilibrium residual over all links and rows.
    type(running_max_t) :: residual
    !> Largest relative mismatch of the driving effort against its independent value.
    type(running_max_t) :: mismatch
    !> |M1 - M_d| over the rows with the true motion, against the moment scale (|M_d|, or the
    !> loads' and inertia's moments when M_d = 0); not seen without a steady cycle.
    type(ratio_of_maxima_t) :: drive_deviation
    !> Peaks of the pair forces with the true motion and at constant speed, in the order
    !> first noted; not allocated without.
    type(force_peak_t), allocatable :: peaks(:)
    !> A mechanism's own maxima over the rows (its layout: the linkage solver's gap); not
    !> allocated without.
    type(running_max_t), allocatable :: maxima(:)
    !> A mechanism's trapezoid integrals over the rows (its layout: the friction works).
    type(trapezoid_t), allocatable :: integrals(:)
    !> A mechanism's flags counted over the rows (its layout: a cam follower jammed, contact
    !> lost).
    type(flag_count_t), allocatable :: flags(:)
    !> Rows of the run tallied so far (kinetostat_summary's tally_rows; run only, as the
    !> members below).
    integer :: rows = 0
    !> Per column: what the rows so far showed (extremes, sums); only the columns the run's
    !> outputs read (step_table_t's tallied) are kept, the others stay at their defaults.
    type(column_tally_t), allocatable :: columns(:)
    !> Input coordinate of the first row tallied.
    real(wp) :: first_at = 0.0_wp
    !> Input coordinate of the last row tallied.
    real(wp) :: last_at = 0.0_wp
    !> Largest input step between two rows so far (unit of the input column).
    real(wp) :: largest_step = 0.0_wp
    !> Twice the driver's work so far (trapezoid sum over its coordinate), J.
    real(wp) :: work2 = 0.0_wp
    !> `work2` of the driver's values and coordinate steps scaled (see column_tally_t's
    !> `area2_scaled`), used when `work2` overflowed.
    real(wp) :: work2_scaled = 0.0_wp
    !> The driver's coordinate in the last row tallied (m, or rad).
    real(wp) :: last_coordinate = 0.0_wp
    !> Input coordinates at the rows next to a load edge (for the coarse-step warning).
    type(edge_point_t), allocatable :: edge_points(:)
    !> Void rows tallied so far.
    integer :: void_rows = 0
  contains
    procedure :: note_peak
  end type run_tally_t

  !> The machine dynamics figures of a run (the DYNAMICS block, JSON "dynamics"): M_d, the
  !> flywheel, the speed's extremes, delta. `present` is false without a steady cycle.
  type :: dynamics_figures_t
    !> Whether the run has a steady cycle (the figures below are set).
    logical :: present = .false.
    !> Mean driving moment over the cycle, N*m.
    real(wp) :: m_d = 0.0_wp
    !> The drive is a moment table (its scale and extremes below are set).
    logical :: drive_table = .false.
    !> Scale the drive's table was given, -.
    real(wp) :: m_d_scale = 0.0_wp
    !> Largest and smallest moment of the drive's table, N*m.
    real(wp) :: m_d_max = 0.0_wp, m_d_min = 0.0_wp
    !> Rotor inertia reduced to the input link, kg*m^2.
    real(wp) :: j_rotor = 0.0_wp
    !> Smallest and largest reduced inertia over the cycle, kg*m^2.
    real(wp) :: j_red_min = 0.0_wp, j_red_max = 0.0_wp
    !> Flywheel inertia, kg*m^2.
    real(wp) :: j_flywheel = 0.0_wp
    !> The textbook's flywheel (delta > 0 only), kg*m^2.
    real(wp) :: j_flywheel_textbook = 0.0_wp
    !> The flywheel drawn as a disc: density of its material, kg/m^3, and its width over its
    !> diameter, b/D (dynamics_records gives its D, b and mass).
    real(wp) :: flywheel_density = 7800.0_wp, flywheel_width_ratio = 0.2_wp
    !> Mean, largest and smallest speed of the input link, rad/s.
    real(wp) :: omega_mean = 0.0_wp, omega_max = 0.0_wp, omega_min = 0.0_wp
    !> Input angles of the largest and smallest speed, deg.
    real(wp) :: phi_omega_max = 0.0_wp, phi_omega_min = 0.0_wp
    !> Coefficient of speed fluctuation asked for (0: none asked), -.
    real(wp) :: delta_asked = 0.0_wp
    !> Coefficient of speed fluctuation of the motion, -.
    real(wp) :: delta = 0.0_wp
    !> Period of the cycle, s.
    real(wp) :: period = 0.0_wp
  end type dynamics_figures_t

contains

  !> The flywheel of `d` as a disc of density rho and width ratio psi = b/D: J = m D^2/8 with
  !> m = rho pi D^2 b/4 gives D = (32 J/(pi rho psi))^(1/5), b = psi D; all 0 without a
  !> flywheel.
  pure subroutine flywheel_disc(d, diameter, width, mass)
    type(dynamics_figures_t), intent(in) :: d
    !> Its diameter D and width b, m.
    real(wp), intent(out) :: diameter, width
    !> Its mass, kg.
    real(wp), intent(out) :: mass
    diameter = 0.0_wp
    width = 0.0_wp
    mass = 0.0_wp
    if (.not. d%j_flywheel > 0.0_wp) return
    diameter = (32.0_wp * d%j_flywheel / (pi * d%flywheel_density * d%flywheel_width_ratio))**0.2_wp
    width = d%flywheel_width_ratio * diameter
    mass = d%flywheel_density * pi * diameter**2 * width / 4.0_wp
  end subroutine flywheel_disc

  !> Note a block's largest value at `row` of the run (a larger one, or a NaN, replaces).
  pure subroutine note_max(self, value, row)
    class(running_max_t), intent(inout) :: self
    !> The block's largest value.
    real(wp), intent(in) :: value
    !> Its row of the run (0: not known).
    integer, intent(in) :: row
    if (self%seen) then
      if (ieee_is_nan(self%value)) return
      if (.not. (value > self%value .or. ieee_is_nan(value))) return
    end if
    self%value = value
    self%row = row
    self%seen = .true.
  end subroutine note_max

  !> Note a block's largest numerator and largest denominator.
  pure subroutine note_ratio(self, numerator, denominator)
    class(ratio_of_maxima_t), intent(inout) :: self
    real(wp), intent(in) :: numerator, denominator
    if (self%seen) then
      self%numerator = max(self%numerator, numerator)
      self%denominator = max(self%denominator, denominator)
    else
      self%numerator = numerator
      self%denominator = denominator
      self%seen = .true.
    end if
  end subroutine note_ratio

  !> max(numerator) / max(denominator) (0 when the denominator is not positive; -1 when
  !> nothing was noted).
  pure real(wp) function ratio(self)
    class(ratio_of_maxima_t), intent(in) :: self
    ratio = -1.0_wp
    if (.not. self%seen) return
    ratio = 0.0_wp
    if (self%denominator > 0.0_wp) ratio = self%numerator / self%denominator
  end function ratio

  !> Note a pair force's peak with the true motion and at constant speed.
  pure subroutine note_peak(self, name, true_motion, constant_speed)
    class(run_tally_t), intent(inout) :: self
    !> Force column ("F16").
    character(*), intent(in) :: name
    !> Largest magnitude with the true motion, N.
    real(wp), intent(in) :: true_motion
    !> The same at constant speed, N.
    real(wp), intent(in) :: constant_speed
    integer :: i
    if (.not. allocated(self%peaks)) allocate (self%peaks(0))
    do i = 1, size(self%peaks)
      if (self%peaks(i)%name /= name) cycle
      self%peaks(i)%true_motion = max(self%peaks(i)%true_motion, true_motion)
      self%peaks(i)%constant_speed = max(self%peaks(i)%constant_speed, constant_speed)
      return
    end do
    self%peaks = [self%peaks, force_peak_t(name, true_motion, constant_speed)]
  end subroutine note_peak

  !> Feed points in row order: for each point after the first of the run the trapezoid
  !> 0.5 |x - x_last| unit (y_last + y).
  pure subroutine feed(self, x, y)
    class(trapezoid_t), intent(inout) :: self
    !> The points' abscissae and ordinates, in row order.
    real(wp), intent(in) :: x(:), y(:)
    integer :: k
    do k = 1, size(x)
      if (self%started) self%area = self%area + 0.5_wp * (abs(x(k) - self%last_x) * self%unit) * (self%last_y + y(k))
      self%last_x = x(k)
      self%last_y = y(k)
      self%started = .true.
    end do
  end subroutine feed

  !> Merge a block's figures into the run's: maxima by max (a NaN stays), the ratio's
  !> numerator and denominator each by max, peaks by max, sums by addition. The blocks
  !> come in row order; the result does not depend on where the run was cut.
  pure subroutine merge_tally(run, block)
    !> The run's figures so far (updated).
    type(run_tally_t), intent(inout) :: run
    !> The figures of the block just solved.
    type(run_tally_t), intent(in) :: block
    integer :: i
    if (block%residual%seen) call run%residual%note(block%residual%value, block%residual%row)
    if (block%mismatch%seen) call run%mismatch%note(block%mismatch%value, block%mismatch%row)
    if (block%drive_deviation%seen) call run%drive_deviation%note(block%drive_deviation%numerator, &
      block%drive_deviation%denominator)
    if (allocated(block%peaks)) then
      do i = 1, size(block%peaks)
        call run%note_peak(block%peaks(i)%name, block%peaks(i)%true_motion, block%peaks(i)%constant_speed)
      end do
    end if
    if (allocated(block%maxima)) then
      if (.not. allocated(run%maxima)) allocate (run%maxima(size(block%maxima)))
      do i = 1, size(block%maxima)
        if (block%maxima(i)%seen) call run%maxima(i)%note(block%maxima(i)%value, block%maxima(i)%row)
      end do
    end if
    if (allocated(block%integrals)) then
      if (.not. allocated(run%integrals)) allocate (run%integrals(size(block%integrals)))
      do i = 1, size(block%integrals)
        run%integrals(i)%unit = block%integrals(i)%unit
        if (allocated(block%integrals(i)%x)) call run%integrals(i)%feed(block%integrals(i)%x, block%integrals(i)%y)
      end do
    end if
    if (allocated(block%flags)) then
      if (.not. allocated(run%flags)) allocate (run%flags(size(block%flags)))
      do i = 1, size(block%flags)
        if (run%flags(i)%first_row == 0) run%flags(i)%first_row = block%flags(i)%first_row
        run%flags(i)%count = run%flags(i)%count + block%flags(i)%count
      end do
    end if
  end subroutine merge_tally

end module kinetostat_run_tally
