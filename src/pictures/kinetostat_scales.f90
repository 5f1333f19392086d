!> Scales of the drawings: the "nice" steps of axes and scale bars, the round scales μ of
!> plans, polygons and force arrows (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 × 10^n per mm), and
!> the drawing scales of ГОСТ 2.302 (1:1, 1:2, 1:2.5, 1:4, 1:5, 1:10 ... 1:50000; 2:1 ...
!> 100:1) with which a mechanism is drawn at μl, written "1:5" in the title block's Масштаб.
module kinetostat_scales
  use kinetostat_kinds, only: wp
  use kinetostat_format, only: fixed_number, short_number
  implicit none
  private
  public :: nice_step, round_scale, drawing_scale_t, standard_drawing_scale, scale_number

  !> Reduction scales of ГОСТ 2.302 (1:n), increasing.
  real(wp), parameter :: reductions(*) = [2.0_wp, 2.5_wp, 4.0_wp, 5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp, &
    40.0_wp, 50.0_wp, 75.0_wp, 100.0_wp, 200.0_wp, 400.0_wp, 500.0_wp, 800.0_wp, 1000.0_wp, 2000.0_wp, 5000.0_wp, &
    10000.0_wp, 20000.0_wp, 25000.0_wp, 50000.0_wp]
  !> Enlargement scales of ГОСТ 2.302 (n:1), increasing.
  real(wp), parameter :: enlargements(*) = [2.0_wp, 2.5_wp, 4.0_wp, 5.0_wp, 10.0_wp, 20.0_wp, 40.0_wp, 50.0_wp, &
    100.0_wp]

  !> A drawing scale: the drawing's length over the true length.
  type :: drawing_scale_t
    !> Ratio (0.2 for 1:5, 2 for 2:1).
    real(wp) :: ratio = 1.0_wp
    !> As ГОСТ 2.302 writes it: "1:5", "1:2.5", "2:1", "1:1".
    character(len=:), allocatable :: text
  end type drawing_scale_t

contains

  !> A "nice" tick or scale-bar step (1, 2 or 5 times a power of ten) near span/count;
  !> angles in degrees spanning 30 deg or more step by 15, 30, 45, 60, 90 or 180 deg.
  pure real(wp) function nice_step(span, count, degrees)
    !> Span to divide, in the quantity's unit (> 0).
    real(wp), intent(in) :: span
    !> About how many steps.
    integer, intent(in) :: count
    !> Whether the quantity is an angle in degrees.
    logical, intent(in) :: degrees
    real(wp), parameter :: angle_steps(*) = [15.0_wp, 30.0_wp, 45.0_wp, 60.0_wp, 90.0_wp, 180.0_wp]
    real(wp) :: raw, p, m
    integer :: i
    raw = span / count
    if (degrees .and. span >= 30.0_wp .and. span <= 2160.0_wp) then
      do i = 1, size(angle_steps)
        nice_step = angle_steps(i)
        if (angle_steps(i) >= raw) return
      end do
      return
    end if
    p = 10.0_wp**floor(log10(raw))
    m = raw / p
    if (m <= 1.0_wp) then
      nice_step = p
    else if (m <= 2.0_wp) then
      nice_step = 2.0_wp * p
    else if (m <= 5.0_wp) then
      nice_step = 5.0_wp * p
    else
      nice_step = 10.0_wp * p
    end if
  end function nice_step

  !> The smallest round scale (1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 × 10^n units per mm) at
  !> which `span` (units) is drawn no longer than `length` mm; 1 for a span of 0.
  pure real(wp) function round_scale(span, length)
    !> The largest value drawn, in its unit (N, m/s, ...).
    real(wp), intent(in) :: span
    !> The room for it, mm.
    real(wp), intent(in) :: length
    real(wp), parameter :: steps(*) = [1.0_wp, 1.2_wp, 1.5_wp, 2.0_wp, 2.5_wp, 3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp, &
      8.0_wp, 10.0_wp]
    real(wp) :: raw, p
    integer :: i
    round_scale = 1.0_wp
    if (.not. span > 0.0_wp .or. .not. length > 0.0_wp) return
    raw = span / length
    p = 10.0_wp**floor(log10(raw))
    do i = 1, size(steps)
      round_scale = steps(i) * p
      if (round_scale >= raw * (1.0_wp - 1.0e-12_wp)) return
    end do
  end function round_scale

  !> The largest drawing scale of ГОСТ 2.302 not above `fit` (the ratio that just fits);
  !> beyond the standard's range the scales go on as 1, 2, 5 × 10^n.
  pure function standard_drawing_scale(fit) result(scale)
    !> The largest ratio that fits (drawing length over true length, > 0).
    real(wp), intent(in) :: fit
    type(drawing_scale_t) :: scale
    real(wp) :: n, p
    integer :: i
    if (fit >= 1.0_wp) then
      scale%ratio = 1.0_wp
      scale%text = "1:1"
      do i = 1, size(enlargements)
        if (enlargements(i) > fit) return
        scale%ratio = enlargements(i)
        scale%text = scale_number(enlargements(i))//":1"
      end do
      ! larger than 100:1: 200, 500, 1000 ... :1
      p = 10.0_wp**floor(log10(fit))
      n = merge(5.0_wp, merge(2.0_wp, 1.0_wp, fit >= 2.0_wp * p), fit >= 5.0_wp * p) * p
      scale%ratio = n
      scale%text = scale_number(n)//":1"
      return
    end if
    do i = 1, size(reductions)
      if (1.0_wp / reductions(i) <= fit) then
        scale%ratio = 1.0_wp / reductions(i)
        scale%text = "1:"//scale_number(reductions(i))
        return
      end if
    end do
    ! smaller than 1:50000: 1:100000, 1:200000, 1:500000 ...
    p = 10.0_wp**ceiling(log10(1.0_wp / fit))
    n = p
    if (1.0_wp / (0.5_wp * p) <= fit) n = 0.5_wp * p
    if (1.0_wp / (0.2_wp * p) <= fit) n = 0.2_wp * p
    scale%ratio = 1.0_wp / n
    scale%text = "1:"//scale_number(n)
  end function standard_drawing_scale

  !> A scale's number as it is written: its decimals without trailing zeros ("2.5", "0.005",
  !> "50000", "1.2E-08" below 1e-6).
  pure function scale_number(x) result(text)
    !> A positive value with at most six significant digits.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    integer :: decimals
    if (.not. abs(x) >= 1.0e-6_wp) then
      text = "0"
      if (x /= 0.0_wp) text = short_number(x)
      return
    end if
    decimals = max(0, 6 - floor(log10(abs(x))))
    text = fixed_number(x, decimals)
    if (index(text, ".") > 0 .and. index(text, "E") == 0) then
      do while (text(len(text):len(text)) == "0")
        text = text(:len(text) - 1)
      end do
      if (text(len(text):len(text)) == ".") text = text(:len(text) - 1)
    end if
  end function scale_number

end module kinetostat_scales
