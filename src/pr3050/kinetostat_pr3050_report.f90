!> PR 3050 run: deck -> all steps -> legacy table (one line per step, E format) or CSV.
module kinetostat_pr3050_report
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, real_str
  use kinetostat_vec2, only: magnitude, angle_360_deg
  use kinetostat_output, only: format_csv, run_summary_t, noise_rel, noise_floor, force_columns, angles_0_360, &
    echo_heading, echo_real, echo_int, echo_array, &
    write_csv_header, write_csv_row, write_selfcheck_footer
  use kinetostat_pr3050, only: pr3050_step_t, pr3050_step, pr3050_check_position
  use kinetostat_deck, only: deck_source_t
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck
  implicit none
  private
  public :: run_pr3050, pr3050_solve, pr3050_csv_columns, pr3050_csv_values

  !> CSV columns, in the spec's order.
  character(*), parameter :: pr3050_csv_columns(*) = [character(len=7) :: &
    "phi3rel", "F14", "F14G", "F34", "F34G", "F32", "F32G", "F2"]
  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> Results header (the original's identifiers) and units.
  character(*), parameter :: header_lines(*) = [character(len=88) :: &
    "     F13G         F14    F14G         F34    F34G         F32    F32G          F2", &
    "      deg           N     deg           N     deg           N     deg           N"]
  !> One line per step: rocker angle from the start, three reactions (magnitude, angle), F2.
  character(*), parameter :: step_line_fmt = '(f9.2,3(e12.3,f8.2),e12.3)'
  !> Heading of the block with the prismatic pair 1-2 and the cylinder's motion.
  character(*), parameter :: pair_heading = &
    "PRISMATIC PAIR 1-2 (ON ROD 2 FROM CYLINDER 1: N21 ALONG E2+90 DEG AT B, M21 CCW) AND CYLINDER"
  !> Header of the prismatic-pair block and units.
  character(*), parameter :: pair_header_lines(*) = [character(len=88) :: &
    "     F13G      PHI2         S      SDOT         N21         M21", &
    "      deg       deg         m       m/s           N         N*m"]
  !> Prismatic-pair line: rocker angle from the start, axis angle B->A, length, rate, N21, M21.
  character(*), parameter :: pair_line_fmt = '(f9.2,f10.2,2f10.4,2e12.3)'

contains

  !> All steps of a validated deck; a geometry error (exit 3) names the step and rocker angle.
  subroutine pr3050_solve(deck, steps, error)
    !> Validated deck.
    type(pr3050_deck_t), intent(in) :: deck
    !> One result per rocker step.
    type(pr3050_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error: "step k (phi3 = x deg): reason".
    type(error_t), allocatable, intent(out) :: error
    integer :: k
    allocate (steps(deck%n))
    do k = 1, deck%n
      call pr3050_check_position(deck%p, deck%phi3_deg(k) * deg_to_rad, error)
      if (allocated(error)) then
        error%message = "step "//int_str(k)//" (phi3 = "//real_str(deck%phi3_deg(k))//" deg): "//error%message
        return
      end if
      steps(k) = pr3050_step(deck%p, deck%phi3_deg(k) * deg_to_rad, deck%omega3(k), deck%eps3(k))
    end do
  end subroutine pr3050_solve

  !> A warning when the rocker passes the dead position (C, B, A collinear: phi3 = k*180 deg,
  !> where s' = 0 and F2 is unbounded) strictly between two computed steps; every step is
  !> valid, but the table does not show the singularity in between.
  pure subroutine dead_position_between_steps(deck, warning)
    !> Validated deck.
    type(pr3050_deck_t), intent(in) :: deck
    !> The warning, unallocated when the range stays clear.
    character(len=:), allocatable, intent(out) :: warning
    integer :: k, half_turns
    do k = 2, deck%n
      half_turns = floor(deck%phi3_deg(k) / 180.0_wp)
      if (floor(deck%phi3_deg(k - 1) / 180.0_wp) /= half_turns .and. &
          modulo(deck%phi3_deg(k), 180.0_wp) /= 0.0_wp) then
        warning = "between step "//int_str(k - 1)//" (phi3 = "//real_str(deck%phi3_deg(k - 1))// &
          " deg) and step "//int_str(k)//" (phi3 = "//real_str(deck%phi3_deg(k))// &
          " deg) the rocker passes the dead position phi3 = "//real_str(180.0_wp * half_turns)// &
          " deg (C, B, A collinear: F2 is unbounded there)"
        return
      end if
    end do
  end subroutine dead_position_between_steps

  !> Read the deck, compute every step, then write the table or CSV to `unit`.
  !> Nothing is written unless the whole run succeeded.
  subroutine run_pr3050(source, output_format, unit, error, summary)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> `format_table` or `format_csv`.
    integer, intent(in) :: output_format
    !> Output unit.
    integer, intent(in) :: unit
    !> Input or geometry error.
    type(error_t), allocatable, intent(out) :: error
    !> Self-check figures of the run.
    type(run_summary_t), intent(out), optional :: summary
    type(pr3050_deck_t) :: deck
    type(pr3050_step_t), allocatable :: steps(:)

    call read_pr3050_deck(source, deck, error)
    if (allocated(error)) return
    call pr3050_solve(deck, steps, error)
    if (allocated(error)) then
      error%message = source%path//": &pr3050: "//error%message
      return
    end if
    if (present(summary)) then
      summary = run_summary_t(size(steps), maxval(steps%residual), maxval(steps%mismatch), "F2")
      call dead_position_between_steps(deck, summary%warning)
    end if
    if (output_format == format_csv) then
      call write_pr3050_csv(unit, deck, steps)
    else
      call write_pr3050_table(unit, source%path, deck, steps)
    end if
  end subroutine run_pr3050

  !> The row of CSV values of one step.
  !> Forces below `noise_rel` times the step's largest force are roundoff: printed as 0 with angle 0.
  pure function pr3050_csv_values(s, phi3rel) result(v)
    !> Results of the step.
    type(pr3050_step_t), intent(in) :: s
    !> Rocker angle from the first step, phi3 - phi3_start (the original's F13G), deg.
    real(wp), intent(in) :: phi3rel
    real(wp) :: v(size(pr3050_csv_columns))
    real(wp) :: floor, f(2, 3)
    f = reshape([s%f14, s%f34, s%f32], [2, 3])
    floor = noise_floor(f, [s%f2])
    v(1) = phi3rel
    v(2:7) = force_columns(f, floor, angles_0_360)
    v(8) = s%f2
    if (abs(v(8)) <= floor) v(8) = 0.0_wp
  end function pr3050_csv_values

  subroutine write_pr3050_csv(unit, deck, steps)
    integer, intent(in) :: unit
    type(pr3050_deck_t), intent(in) :: deck
    type(pr3050_step_t), intent(in) :: steps(:)
    integer :: k
    call write_csv_header(unit, pr3050_csv_columns)
    do k = 1, size(steps)
      call write_csv_row(unit, pr3050_csv_values(steps(k), phi3rel(deck, k)))
    end do
  end subroutine write_pr3050_csv

  subroutine write_pr3050_table(unit, path, deck, steps)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(pr3050_deck_t), intent(in) :: deck
    type(pr3050_step_t), intent(in) :: steps(:)
    real(wp) :: v(size(pr3050_csv_columns)), floor, n21, m21
    integer :: k

    write (unit, title_fmt) "KINETOSTAT  PR 3050  FORCE ANALYSIS OF THE FOUR-BAR WITH AN OSCILLATING HYDRAULIC CYLINDER"
    write (unit, title_fmt) "DECK: "//path
    call echo_heading(unit, "INPUT DATA")
    call echo_real(unit, "L_CA", deck%p%l_ca, "m")
    call echo_real(unit, "L_CB", deck%p%l_cb, "m")
    call echo_real(unit, "L_CS3", deck%p%l_cs3, "m")
    call echo_real(unit, "DELTA", deck%delta_deg, "deg")
    call echo_real(unit, "L_BS2", deck%p%l_bs2, "m")
    call echo_real(unit, "L_S1A", deck%p%l_s1a, "m")
    call echo_real(unit, "GAMMA", deck%gamma_deg, "deg")
    call echo_real(unit, "G", deck%p%g, "m/s^2")
    call echo_real(unit, "M1", deck%p%m1, "kg")
    call echo_real(unit, "M2", deck%p%m2, "kg")
    call echo_real(unit, "M3", deck%p%m3, "kg")
    call echo_real(unit, "J1", deck%p%j1, "kg*m^2")
    call echo_real(unit, "J2", deck%p%j2, "kg*m^2")
    call echo_real(unit, "J3", deck%p%j3, "kg*m^2")
    call echo_real(unit, "PHI3_START", deck%phi3_start, "deg")
    call echo_real(unit, "PHI3_END", deck%phi3_end, "deg")
    call echo_real(unit, "DPHI3", deck%dphi3, "deg")
    call echo_int(unit, "N", deck%n, "steps")
    call echo_array(unit, "OMEGA3", deck%omega3, "rad/s")
    call echo_array(unit, "EPS3", deck%eps3, "rad/s^2")

    call echo_heading(unit, "RESULTS")
    do k = 1, size(header_lines)
      write (unit, '(a)') trim(header_lines(k))
    end do
    do k = 1, size(steps)
      v = pr3050_csv_values(steps(k), phi3rel(deck, k))
      write (unit, step_line_fmt) v
    end do

    call echo_heading(unit, pair_heading)
    do k = 1, size(pair_header_lines)
      write (unit, '(a)') trim(pair_header_lines(k))
    end do
    do k = 1, size(steps)
      v = pr3050_csv_values(steps(k), phi3rel(deck, k))
      floor = noise_rel * maxval(abs(v(2:8:2)))
      n21 = steps(k)%n21
      if (abs(n21) <= floor) n21 = 0.0_wp
      m21 = steps(k)%m21
      if (abs(m21) <= floor * (deck%p%l_ca + deck%p%l_cb)) m21 = 0.0_wp
      write (unit, pair_line_fmt) v(1), angle_360_deg([cos(steps(k)%phi2), sin(steps(k)%phi2)]), steps(k)%s, &
        steps(k)%s_dot + 0.0_wp, n21 + 0.0_wp, m21 + 0.0_wp
    end do
    call write_selfcheck_footer(unit, maxval(steps%residual), maxval(steps%mismatch), "F2")
  end subroutine write_pr3050_table

  !> Rocker angle of step `k` from the first step, (k - 1)*dphi3, deg.
  pure function phi3rel(deck, k) result(angle)
    type(pr3050_deck_t), intent(in) :: deck
    integer, intent(in) :: k
    real(wp) :: angle
    angle = real(k - 1, wp) * deck%dphi3
  end function phi3rel

end module kinetostat_pr3050_report
