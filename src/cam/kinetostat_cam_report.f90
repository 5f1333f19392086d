!> Cam run: deck -> all cam angles -> table (one line per step) or CSV.
module kinetostat_cam_report
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_vec2, only: magnitude, angle_360_deg
  use kinetostat_output, only: run_summary_t, format_csv, echo_heading, echo_real, echo_int, echo_array, &
    write_csv_header, write_csv_row
  use kinetostat_selfcheck, only: selfcheck_tolerance
  use kinetostat_cam, only: cam_step_t, cam_step, cam_critical_angle, kf_limit
  use kinetostat_deck, only: deck_source_t
  use kinetostat_cam_deck, only: cam_deck_t, read_cam_deck, follower_translating
  implicit none
  private
  public :: run_cam, cam_solve, cam_csv_columns, cam_csv_values

  !> CSV columns, one row per cam angle; see README "Cam mechanisms".
  character(*), parameter :: cam_csv_columns(*) = [character(len=5) :: &
    "phi", "theta", "xB", "F2", "vdir", "N", "F21", "F21G", "F23C", "F23CG", "F23D", "F23DG", &
    "KF", "KF2", "JAM", "LOST"]
  !> Self-check footer lines (as the shared footer).
  character(*), parameter :: footer_fmt = '(3x,a,t58,es10.2,2x,a)'
  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> A text value in the INPUT DATA block.
  character(*), parameter :: echo_text_fmt = '(3x,a,t20,"=",2x,a)'
  !> Results header with units.
  character(*), parameter :: header_lines(*) = [character(len=128) :: &
    "     PHI   THETA        XB         F2  V          F21    F21G         F23C   F23CG" // &
    "         F23D   F23DG        KF  FLAGS", &
    "     deg     deg         m          N             N     deg            N     deg" // &
    "            N     deg"]
  !> One step: angle, pressure angle, offset, load, motion, three forces with angles, K_F.
  character(*), parameter :: step_fmt = '(f8.2,f8.3,f10.5,f11.2,i3,3(f13.3,f8.2),f10.4,2x,a)'
  !> A step without finite forces (jammed or contact lost): the flags replace the numbers.
  character(*), parameter :: step_void_fmt = '(f8.2,f8.3,f10.5,f11.2,i3,2x,a)'

contains

  !> All steps of a validated deck.
  pure subroutine cam_solve(deck, steps)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> One result per cam angle.
    type(cam_step_t), allocatable, intent(out) :: steps(:)
    integer :: k
    allocate (steps(deck%n))
    do k = 1, deck%n
      steps(k) = cam_step(deck%p, deck%theta_deg(k) * deg_to_rad, deck%x_b(k), deck%mu_cam, &
                          deck%f2(k), deck%vdir(k))
    end do
  end subroutine cam_solve

  !> Read the deck, compute every step, then write the table or CSV to `unit`.
  subroutine run_cam(source, output_format, unit, error, summary)
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
    type(cam_deck_t) :: deck
    type(cam_step_t), allocatable :: steps(:)
    integer :: i
    !> Word for one output row in messages.
    character(*), parameter :: row_name = "step"
    call read_cam_deck(source, deck, error)
    if (allocated(error)) return
    call cam_solve(deck, steps)
    do i = 1, size(steps)
      if (.not. all(ieee_is_finite(cam_csv_values(deck, steps(i), i)))) then
        call fatal_error(error, exit_input, source%path//": results overflow at "//row_name//" "//int_str(i)// &
          ": input values out of the representable range")
        return
      end if
    end do
    if (present(summary)) summary = run_summary_t(size(steps), maxval(steps%residual), &
                                                  maxval(steps%mismatch), "N")
    if (output_format == format_csv) then
      call write_cam_csv(unit, deck, steps)
    else
      call write_cam_table(unit, source%path, deck, steps)
    end if
  end subroutine run_cam

  !> The CSV row of step k (flags as 0/1; forces 0 when jammed or contact lost).
  pure function cam_csv_values(deck, s, k) result(v)
    type(cam_deck_t), intent(in) :: deck
    type(cam_step_t), intent(in) :: s
    integer, intent(in) :: k
    real(wp) :: v(size(cam_csv_columns))
    v(1) = deck%phi_deg(k)
    v(2) = deck%theta_deg(k)
    v(3) = deck%x_b(k)
    v(4) = deck%f2(k)
    v(5) = deck%vdir(k)
    v(6) = s%n
    v(7) = magnitude(s%f21)
    v(8) = angle_360_deg(s%f21)
    v(9) = magnitude(s%f23c)
    v(10) = angle_360_deg(s%f23c)
    v(11) = magnitude(s%f23d)
    v(12) = angle_360_deg(s%f23d)
    v(13) = s%kf
    v(14) = merge(1.0_wp, 0.0_wp, s%kf_over)
    v(15) = merge(1.0_wp, 0.0_wp, s%jammed)
    v(16) = merge(1.0_wp, 0.0_wp, s%lost)
  end function cam_csv_values

  subroutine write_cam_csv(unit, deck, steps)
    integer, intent(in) :: unit
    type(cam_deck_t), intent(in) :: deck
    type(cam_step_t), intent(in) :: steps(:)
    integer :: k
    call write_csv_header(unit, cam_csv_columns)
    do k = 1, size(steps)
      call write_csv_row(unit, cam_csv_values(deck, steps(k), k))
    end do
  end subroutine write_cam_csv

  !> Flag text of one step.
  pure function flags_text(s) result(t)
    type(cam_step_t), intent(in) :: s
    character(len=:), allocatable :: t
    t = ""
    if (s%lost) then
      t = "LOST CONTACT (F2 <= 0)"
    else if (s%jammed) then
      t = "JAMMED (SELF-LOCKING)"
    else if (s%kf_over) then
      t = "KF>2"
    end if
  end function flags_text

  subroutine write_cam_table(unit, path, deck, steps)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(cam_deck_t), intent(in) :: deck
    type(cam_step_t), intent(in) :: steps(:)
    real(wp) :: v(size(cam_csv_columns))
    integer :: k

    write (unit, title_fmt) "KINETOSTAT  CAM  FORCES ON A TRANSLATING FOLLOWER IN A GUIDE (MANUAL SECTION 7)"
    write (unit, title_fmt) "DECK: "//path
    call echo_heading(unit, "INPUT DATA")
    if (deck%follower == follower_translating) then
      write (unit, echo_text_fmt) "FOLLOWER", "translating (knife/roller)"
    else
      write (unit, echo_text_fmt) "FOLLOWER", "flat"
    end if
    call echo_real(unit, "L", deck%p%l, "m")
    call echo_real(unit, "L_OVER", deck%p%a, "m")
    call echo_real(unit, "F", deck%p%f, "")
    if (deck%follower /= follower_translating) then
      call echo_real(unit, "F_CAM", deck%f_cam, "")
      call echo_real(unit, "OMEGA_DIR", deck%omega_dir, "(+1 CCW, -1 CW)")
    end if
    call echo_real(unit, "PHI_START", deck%phi_start, "deg")
    call echo_real(unit, "DPHI", deck%dphi, "deg")
    call echo_int(unit, "N", deck%n, "steps")
    if (deck%follower == follower_translating) then
      call echo_array(unit, "THETA", deck%theta_deg(1:max(1, min(deck%n, deck%given(1)))), "deg")
    else
      call echo_array(unit, "DS_DPHI", deck%ds_dphi(1:max(1, min(deck%n, deck%given(4)))), "m/rad")
    end if
    call echo_array(unit, "F2", deck%f2(1:max(1, min(deck%n, deck%given(2)))), "N")
    if (deck%follower == follower_translating) &
      call echo_array(unit, "VDIR", deck%vdir(1:max(1, min(deck%n, deck%given(3)))), "")
    if (deck%follower == follower_translating) &
      call echo_real(unit, "THETA_CR", cam_critical_angle(deck%p) * rad_to_deg, "deg (rise; derived)")
    call echo_real(unit, "KF_LIMIT", kf_limit, "(Reshetov)")

    call echo_heading(unit, "RESULTS")
    do k = 1, size(header_lines)
      write (unit, '(a)') trim(header_lines(k))
    end do
    do k = 1, size(steps)
      v = cam_csv_values(deck, steps(k), k)
      if (steps(k)%jammed .or. steps(k)%lost) then
        write (unit, step_void_fmt) v(1), v(2), v(3), v(4), nint(v(5)), flags_text(steps(k))
      else
        write (unit, step_fmt) v(1), v(2), v(3), v(4), nint(v(5)), v(7), v(8), v(9), v(10), v(11), v(12), v(13), &
          flags_text(steps(k))
      end if
    end do
    call write_cam_footer(unit, maxval(steps%residual), maxval(steps%mismatch))
  end subroutine write_cam_table

  !> Self-check footer: follower equilibrium, and N of the closed form against a 3x3 solve
  !> (a cam follower has no independent power balance: its only work term is the axis one).
  subroutine write_cam_footer(unit, max_residual, max_mismatch)
    integer, intent(in) :: unit
    real(wp), intent(in) :: max_residual, max_mismatch
    character(len=16) :: tol
    write (tol, '(es8.1)') selfcheck_tolerance
    call echo_heading(unit, "SELF-CHECK (relative; limit "//trim(adjustl(tol))//")")
    write (unit, footer_fmt) "MAX EQUILIBRIUM RESIDUAL OF THE FOLLOWER, ALL STEPS", max_residual, &
      verdict(max_residual)
    write (unit, footer_fmt) "MAX N MISMATCH, CLOSED FORM VS 3X3 LINEAR SOLVE", max_mismatch, verdict(max_mismatch)
  end subroutine write_cam_footer

  pure function verdict(x) result(t)
    real(wp), intent(in) :: x
    character(len=2) :: t
    t = "OK"
    if (.not. x <= selfcheck_tolerance) t = "!!"
  end function verdict

end module kinetostat_cam_report
