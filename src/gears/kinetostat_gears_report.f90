!> Gears run: deck -> every stage -> table (one block per stage) or CSV (one row per stage).
module kinetostat_gears_report
  use kinetostat_kinds, only: wp, rad_to_deg
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_vec2, only: magnitude, angle_360_deg, snap_noise
  use kinetostat_output, only: run_summary_t, format_csv, echo_heading, echo_real, echo_int, &
    write_csv_header, write_csv_row, write_selfcheck_footer
  use kinetostat_gears, only: gear_stage_t, gear_result_t, gear_pair, gear_series, gear_planetary_step, &
    gear_planetary, gear_bevel, gear_kind_names
  use kinetostat_deck, only: deck_source_t
  use kinetostat_gears_deck, only: gears_deck_t, read_gears_deck, layout_series, layout_names
  implicit none
  private
  public :: run_gears, gears_solve, gears_csv_columns, gears_csv_values

  !> CSV columns (one row per stage); see README "Gear meshes".
  character(*), parameter :: gears_csv_columns(*) = [character(len=6) :: &
    "stage", "kind", "z1", "z2", "z3", "k", "dw1", "dw2", "u", "M1", "M2", "M2P", &
    "Ft", "Fr1", "Fa1", "Fr2", "Fa2", "Fn", "F12", "F12G", "FS1", "FS1G", "FS2", "FS2G", &
    "F23", "F23G", "F2H", "F2HG", "M3", "M3P"]
  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> Stage heading in the INPUT DATA and RESULTS blocks.
  character(*), parameter :: stage_fmt = '(/,1x,"STAGE ",i0,": ",a)'
  !> A text value in the INPUT DATA block (e.g. the layout).
  character(*), parameter :: echo_text_fmt = '(3x,a,t20,"=",2x,a)'
  !> A force vector in the RESULTS block: magnitude and angle.
  character(*), parameter :: vector_fmt = '(3x,a,t20,"=",es18.9,2x,"N",3x,"ANGLE =",f11.4,2x,"deg")'
  !> CSV positions of the torque columns (M1, M2, M2P, M3, M3P).
  integer, parameter :: moment_columns(*) = [10, 11, 12, 29, 30]
  !> Relative roundoff floor below which a force counts as zero in the output.
  real(wp), parameter :: noise_rel = 1.0e-12_wp

contains

  !> All stages of a validated deck.
  pure subroutine gears_solve(deck, res)
    !> Validated deck.
    type(gears_deck_t), intent(in) :: deck
    !> One result per stage.
    type(gear_result_t), allocatable, intent(out) :: res(:)
    integer :: i
    allocate (res(deck%n))
    if (deck%layout == layout_series) then
      call gear_series(deck%st, deck%m1(1), res)
    else
      do i = 1, deck%n
        if (deck%st(i)%kind == gear_planetary) then
          res(i) = gear_planetary_step(deck%st(i), deck%m1(i))
        else
          res(i) = gear_pair(deck%st(i), deck%m1(i), [0.0_wp, 0.0_wp])
        end if
      end do
    end if
  end subroutine gears_solve

  !> Read the deck, compute every stage, then write the table or CSV to `unit`.
  subroutine run_gears(source, output_format, unit, error, summary)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> `format_table` or `format_csv`.
    integer, intent(in) :: output_format
    !> Output unit.
    integer, intent(in) :: unit
    !> Input error from the deck.
    type(error_t), allocatable, intent(out) :: error
    !> Self-check figures of the run.
    type(run_summary_t), intent(out), optional :: summary
    type(gears_deck_t) :: deck
    type(gear_result_t), allocatable :: res(:)
    integer :: i
    !> Word for one output row in messages.
    character(*), parameter :: row_name = "stage"
    call read_gears_deck(source, deck, error)
    if (allocated(error)) return
    call gears_solve(deck, res)
    do i = 1, size(res)
      if (.not. all(ieee_is_finite(gears_csv_values(deck, res, i)))) then
        call fatal_error(error, exit_input, source%path//": results overflow at "//row_name//" "//int_str(i)// &
          ": input values out of the representable range")
        return
      end if
    end do
    if (present(summary)) summary = run_summary_t(size(res), maxval(res%residual), &
                                                  maxval(res%mismatch), "M2")
    if (output_format == format_csv) then
      call write_gears_csv(unit, deck, res)
    else
      call write_gears_table(unit, source%path, deck, res)
    end if
  end subroutine run_gears

  !> The CSV row of stage `i`: diameters in mm, forces N (magnitude) and deg (angle).
  pure function gears_csv_values(deck, res, i) result(v)
    type(gears_deck_t), intent(in) :: deck
    type(gear_result_t), intent(in) :: res(:)
    integer, intent(in) :: i
    real(wp) :: v(size(gears_csv_columns))
    type(gear_stage_t) :: st
    type(gear_result_t) :: r
    real(wp) :: floor, f(2, 5)
    integer :: j
    st = deck%st(i)
    r = res(i)
    f = reshape([r%f12, r%fs1, r%fs2, r%f23, r%f2h], [2, 5])
    floor = noise_rel * maxval([(magnitude(f(:, j)), j=1, 5)])
    do j = 1, 5
      f(:, j) = snap_noise(f(:, j), floor)
    end do
    v(1) = real(i, wp)
    v(2) = real(st%kind, wp)
    v(3) = real(st%z1, wp)
    v(4) = real(st%z2, wp)
    v(5) = real(st%z3, wp)
    v(6) = real(st%k, wp)
    if (st%kind /= gear_planetary) v(6) = 0.0_wp
    v(7) = st%dw1 * 1.0e3_wp
    v(8) = r%dw2 * 1.0e3_wp
    v(9) = r%u
    v(10:12) = [r%m1, r%m2, r%m2_power]
    v(13:18) = [r%ft, r%fr1, r%fa1, r%fr2, r%fa2, r%fn]
    do j = 1, 5
      v(17 + 2 * j) = magnitude(f(:, j))
      v(18 + 2 * j) = angle_360_deg(f(:, j))
    end do
    v(29:30) = [r%m_house, r%m_house_power]
    ! torques: roundoff relative to the stage's largest torque prints as 0
    floor = noise_rel * maxval(abs([v(10:12), v(29:30)]))
    do j = 1, size(moment_columns)
      if (abs(v(moment_columns(j))) <= floor) v(moment_columns(j)) = 0.0_wp
    end do
  end function gears_csv_values

  subroutine write_gears_csv(unit, deck, res)
    integer, intent(in) :: unit
    type(gears_deck_t), intent(in) :: deck
    type(gear_result_t), intent(in) :: res(:)
    integer :: i
    call write_csv_header(unit, gears_csv_columns)
    do i = 1, size(res)
      call write_csv_row(unit, gears_csv_values(deck, res, i))
    end do
  end subroutine write_gears_csv

  subroutine write_gears_table(unit, path, deck, res)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(gears_deck_t), intent(in) :: deck
    type(gear_result_t), intent(in) :: res(:)
    type(gear_stage_t) :: st
    real(wp) :: v(size(gears_csv_columns))
    integer :: i

    write (unit, title_fmt) "KINETOSTAT  GEARS  FORCES IN GEAR MESHES (MANUAL SECTION 6, FRICTION-FREE)"
    write (unit, title_fmt) "DECK: "//path
    call echo_heading(unit, "INPUT DATA")
    write (unit, echo_text_fmt) "LAYOUT", trim(layout_names(deck%layout))
    call echo_int(unit, "STAGES", deck%n, "")
    do i = 1, deck%n
      st = deck%st(i)
      write (unit, stage_fmt) i, trim(to_upper(gear_kind_names(st%kind)))
      if (deck%layout /= layout_series .or. i == 1) call echo_real(unit, "M1", deck%m1(i), "N*m")
      call echo_int(unit, "Z1", st%z1, "")
      call echo_int(unit, "Z2", st%z2, "")
      if (st%kind == gear_planetary) then
        call echo_int(unit, "Z3", st%z3, "")
        call echo_int(unit, "K", st%k, "satellites")
      end if
      if (deck%module_mm(i) > 0.0_wp) call echo_real(unit, "M", deck%module_mm(i), "mm")
      call echo_real(unit, "DW1", st%dw1 * 1.0e3_wp, "mm")
      call echo_real(unit, "ALPHA_W", st%alpha_w * rad_to_deg, "deg")
      if (st%kind == gear_planetary) call echo_real(unit, "ALPHA_W23", st%alpha_w23 * rad_to_deg, "deg")
      if (st%kind == gear_bevel) call echo_real(unit, "DELTA1", st%delta1 * rad_to_deg, "deg (atan(z1/z2))")
      call echo_real(unit, "BETA", st%beta * rad_to_deg, "deg")
      call echo_real(unit, "GAMMA", st%gamma * rad_to_deg, "deg")
    end do

    call echo_heading(unit, "RESULTS")
    do i = 1, deck%n
      st = deck%st(i)
      v = gears_csv_values(deck, res, i)
      write (unit, stage_fmt) i, trim(to_upper(gear_kind_names(st%kind)))
      call echo_real(unit, "DW2", v(8), "mm")
      call echo_real(unit, "U", v(9), "")
      call echo_real(unit, "M1", v(10), "N*m")
      call echo_real(unit, "FT", v(13), "N")
      call echo_real(unit, "FR1", v(14), "N")
      call echo_real(unit, "FA1", v(15), "N")
      call echo_real(unit, "FR2", v(16), "N")
      call echo_real(unit, "FA2", v(17), "N")
      call echo_real(unit, "FN", v(18), "N")
      write (unit, vector_fmt) "F12", v(19), v(20)
      write (unit, vector_fmt) "FS1", v(21), v(22)
      if (st%kind /= gear_bevel) write (unit, vector_fmt) "FS2", v(23), v(24)
      if (st%kind == gear_planetary) then
        write (unit, vector_fmt) "F23", v(25), v(26)
        write (unit, vector_fmt) "F2H", v(27), v(28)
        call echo_real(unit, "M_H", v(11), "N*m (carrier, from forces)")
        call echo_real(unit, "M_H POWER", v(12), "N*m (M1*u_1H)")
        call echo_real(unit, "M3 HOUSING", v(29), "N*m (on the ring, from forces)")
        call echo_real(unit, "M3 BALANCE", v(30), "N*m (M1 - M_H)")
      else
        call echo_real(unit, "M2", v(11), "N*m (from forces)")
        call echo_real(unit, "M2 POWER", v(12), "N*m (power balance)")
      end if
    end do
    call write_selfcheck_footer(unit, maxval(res%residual), maxval(res%mismatch), "M2")
  end subroutine write_gears_table

  pure function to_upper(s) result(t)
    character(*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('a') .and. c <= iachar('z')) t(i:i) = achar(c - 32)
    end do
  end function to_upper

end module kinetostat_gears_report
