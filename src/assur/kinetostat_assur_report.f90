!> Generic mechanism run: `&assur` deck -> all steps -> table (magnitudes / angles / normal
!> forces / reaction moments per step) or CSV (`phi1`, every pair, crank pin, `M1`).
module kinetostat_assur_report
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str, real_str
  use kinetostat_vec2, only: magnitude, angle_360_deg, angle_180_deg, rotate, snap_noise, clean_zero
  use kinetostat_output, only: format_csv, run_summary_t, echo_heading, echo_real, echo_int, echo_logical, echo_array, &
    write_csv_header, write_csv_row, write_selfcheck_footer
  use kinetostat_assur_kinematics, only: kind_names
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_step_t, assur_step
  use kinetostat_deck, only: deck_source_t
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck
  implicit none
  private
  public :: run_assur, assur_solve, assur_csv_columns, assur_csv_values, assur_pair_prismatic

  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> Relative roundoff floor below which a force counts as zero in the output.
  real(wp), parameter :: noise_rel = 1.0e-12_wp
  !> Results header: a label in the PHI1 column then 12-wide names.
  character(*), parameter :: header_fmt = '(a9,*(a12))'
  !> Step line 1 starts with the crank angle.
  character(*), parameter :: phi_fmt = '(f9.2)'
  !> One 12-wide numeric field (forces, angles, moments).
  character(*), parameter :: field_fmt = '(f12.2)'
  !> The same field for values too large for field_fmt (|x| >= 1e8).
  character(*), parameter :: field_big_fmt = '(es12.4)'
  !> Dyad line of the INPUT DATA echo.
  character(*), parameter :: dyad_echo_fmt = '(3x,"DYAD ",i0,": ",a," LINKS ",i0,"-",i0,", ON LINKS ",i0," AND ",i0, &
    &", MODE ",i0)'

contains

  !> Whether result pair `ip` (dyad pairs then crank pin) is prismatic.
  pure logical function assur_pair_prismatic(deck, ip)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Pair result index.
    integer, intent(in) :: ip
    integer :: d
    d = (ip - 1) / 3 + 1
    if (d > size(deck%mech%dyads)) then
      assur_pair_prismatic = .false.
    else
      assur_pair_prismatic = pair_is_prismatic(deck%mech%dyads(d)%geom%kind, ip - 3 * (d - 1))
    end if
  end function assur_pair_prismatic

  !> All steps of a validated deck; a geometry error names the step and the input angle.
  pure subroutine assur_solve(path, deck, steps, error)
    !> Deck file (for messages).
    character(*), intent(in) :: path
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> One result per step.
    type(assur_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error.
    type(error_t), allocatable, intent(out) :: error
    type(error_t), allocatable :: step_error
    character(len=32) :: angle_text
    integer :: k
    allocate (steps(deck%n))
    do k = 1, deck%n
      call assur_step(deck%mech, deck%phi1_deg(k) * deg_to_rad, deck%omega1(k), deck%eps1(k), &
                      deck%f_mag(:, k), deck%m_mag(:, k), steps(k), step_error)
      if (allocated(step_error)) then
        write (angle_text, '(g0.10)') deck%phi1_deg(k)
        call fatal_error(error, exit_geometry, path//": &assur: step "//int_str(k)//" (phi1 = "// &
          trim(adjustl(angle_text))//" deg): "//step_error%message)
        return
      end if
    end do
  end subroutine assur_solve

  !> Read the deck, compute every step, then write the table or CSV to `unit`.
  subroutine run_assur(source, output_format, unit, error, summary)
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
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    call read_assur_deck(source, deck, error)
    if (allocated(error)) return
    call assur_solve(source%path, deck, steps, error)
    if (allocated(error)) return
    if (present(summary)) summary = run_summary_t(size(steps), maxval(steps%residual), &
                                                  maxval(steps%mismatch), "M1")
    if (output_format == format_csv) then
      call write_assur_csv(unit, deck, steps)
    else
      call write_assur_table(unit, source%path, deck, steps)
    end if
  end subroutine run_assur

  !> CSV column names: phi1; per pair F, FG, [Fx, Fy], [FN, FM for prismatic pairs]; M1.
  pure function assur_csv_columns(deck) result(cols)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    character(len=24), allocatable :: cols(:)
    integer :: ip
    cols = [character(len=24) :: "phi1"]
    do ip = 1, size(deck%pair_name)
      cols = [character(len=24) :: cols, trim(deck%pair_name(ip)), trim(deck%pair_name(ip))//"G"]
      if (deck%components) cols = [character(len=24) :: cols, trim(deck%pair_name(ip))//"x", &
                                   trim(deck%pair_name(ip))//"y"]
      if (assur_pair_prismatic(deck, ip)) cols = [character(len=24) :: cols, trim(deck%pair_name(ip))//"N", &
                                                  trim(deck%pair_name(ip))//"M"]
    end do
    cols = [character(len=24) :: cols, "M1"]
  end function assur_csv_columns

  !> The CSV row of one step, in the order of assur_csv_columns. Forces below `noise_rel`
  !> times the step's largest force (moments below that force times the crank's length
  !> scale) are roundoff: printed as 0 with angle 0; so are single components below that floor
  !> (a force along an axis gets exactly that axis' angle).
  pure function assur_csv_values(deck, s) result(v)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> One step.
    type(assur_step_t), intent(in) :: s
    real(wp), allocatable :: v(:)
    real(wp) :: floor, f(2), mfloor, nn, mm
    integer :: ip, np, pos
    np = size(s%f, 2)
    allocate (v(1 + 6 * np + 1))
    floor = 0.0_wp
    do ip = 1, np
      floor = max(floor, magnitude(s%f(:, ip)))
    end do
    floor = noise_rel * floor
    mfloor = floor * crank_length(deck)
    v(1) = s%phi1 * rad_to_deg
    pos = 1
    do ip = 1, np
      f = rotate(snap_noise(deck%pair_sign(ip) * s%f(:, ip), floor), -deck%pair_frame(ip))
      where (abs(f) <= floor) f = 0.0_wp
      v(pos + 1) = magnitude(f)
      if (deck%angles_signed) then
        v(pos + 2) = angle_180_deg(f)
      else
        v(pos + 2) = angle_360_deg(f)
      end if
      pos = pos + 2
      if (deck%components) then
        v(pos + 1:pos + 2) = f
        pos = pos + 2
      end if
      if (assur_pair_prismatic(deck, ip)) then
        nn = deck%pair_sign(ip) * s%n(ip)
        mm = deck%pair_sign(ip) * s%m(ip)
        if (abs(nn) <= floor) nn = 0.0_wp
        if (abs(mm) <= mfloor) mm = 0.0_wp
        v(pos + 1:pos + 2) = [nn, mm]
        pos = pos + 2
      end if
    end do
    v(pos + 1) = s%m1
    if (abs(v(pos + 1)) <= mfloor) v(pos + 1) = 0.0_wp
    v = clean_zero(v(1:pos + 1))
  end function assur_csv_values

  !> Length scale of the crank: its farthest attachment point from the pivot (1 m if none).
  pure real(wp) function crank_length(deck)
    type(assur_deck_t), intent(in) :: deck
    integer :: d, q
    crank_length = 0.0_wp
    do d = 1, size(deck%mech%dyads)
      do q = 1, 2
        if (deck%mech%dyads(d)%on(q) == 1) crank_length = max(crank_length, magnitude(deck%mech%dyads(d)%at(:, q)))
      end do
    end do
    if (.not. crank_length > 0.0_wp) crank_length = 1.0_wp
  end function crank_length

  !> A 12-wide table field: fixed point, or exponent form when too large (never '*').
  pure function field12(x) result(text)
    real(wp), intent(in) :: x
    character(len=12) :: text
    if (abs(x) < 1.0e8_wp) then
      write (text, field_fmt) x
    else
      write (text, field_big_fmt) x
    end if
  end function field12

  !> A 12-wide right-adjusted header label `name//suffix`, blank when `show` is false.
  pure function p_label(name, suffix, show) result(label)
    character(*), intent(in) :: name, suffix
    logical, intent(in) :: show
    character(len=12) :: label
    label = ""
    if (show) label = adjustr(trim(name)//suffix)
  end function p_label

  subroutine write_assur_csv(unit, deck, steps)
    integer, intent(in) :: unit
    type(assur_deck_t), intent(in) :: deck
    type(assur_step_t), intent(in) :: steps(:)
    integer :: k
    call write_csv_header(unit, assur_csv_columns(deck))
    do k = 1, size(steps)
      call write_csv_row(unit, assur_csv_values(deck, steps(k)))
    end do
  end subroutine write_assur_csv

  subroutine write_assur_table(unit, path, deck, steps)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(assur_deck_t), intent(in) :: deck
    type(assur_step_t), intent(in) :: steps(:)
    character(len=12), allocatable :: names(:)
    character(len=:), allocatable :: line1, line2, line3, line4
    character(len=12) :: buf
    real(wp), allocatable :: v(:)
    real(wp) :: mag(size(deck%pair_name)), ang(size(deck%pair_name)), nn(size(deck%pair_name))
    real(wp) :: mm(size(deck%pair_name)), m1
    integer :: k, ip, np, pos, d
    logical :: any_p

    np = size(deck%pair_name)
    write (unit, title_fmt) "KINETOSTAT  ASSUR  FORCE ANALYSIS OF A LINKAGE OF CLASS-II ASSUR GROUPS"
    write (unit, title_fmt) "DECK: "//path
    if (len_trim(deck%title) > 0) write (unit, title_fmt) "TITLE: "//trim(deck%title)
    call echo_heading(unit, "INPUT DATA")
    call echo_int(unit, "FRAME_ID", deck%frame_id, "")
    call echo_int(unit, "CRANK_ID", deck%crank_id, "")
    call echo_array(unit, "CRANK_AT", deck%mech%pivot, "m")
    call echo_real(unit, "CRANK_M", deck%mech%links(1)%m, "kg")
    call echo_real(unit, "CRANK_J", deck%mech%links(1)%j, "kg*m^2")
    call echo_array(unit, "CRANK_S", deck%mech%links(1)%s, "m")
    if (deck%prescribed) then
      call echo_array(unit, "OMEGA1_STEP", deck%omega1, "rad/s")
      call echo_array(unit, "EPS1_STEP", deck%eps1, "rad/s^2")
    else
      call echo_real(unit, "OMEGA1", deck%omega1_const, "rad/s")
    end if
    call echo_real(unit, "G", deck%mech%g, "m/s^2")
    call echo_real(unit, "GRAVITY_ANGLE", deck%gravity_angle, "deg")
    call echo_real(unit, "PHI_START", deck%phi_start, "deg")
    call echo_real(unit, "DPHI", deck%dphi, "deg")
    call echo_int(unit, "N", deck%n, "steps")
    call echo_logical(unit, "ANGLES_SIGNED", deck%angles_signed, "")
    call echo_logical(unit, "COMPONENTS", deck%components, "")
    do d = 1, size(deck%mech%dyads)
      associate (dy => deck%mech%dyads(d), lk => deck%mech%links)
        write (unit, dyad_echo_fmt) d, kind_names(dy%geom%kind), lk(2 * d)%id, lk(2 * d + 1)%id, &
          lk(dy%on(1))%id, lk(dy%on(2))%id, dy%geom%mode
        call echo_array(unit, "AT2", dy%at(:, 1), "m")
        call echo_array(unit, "AT3", dy%at(:, 2), "m")
        call echo_real(unit, "ANGLE2", dy%ang(1) * rad_to_deg, "deg")
        call echo_real(unit, "ANGLE3", dy%ang(2) * rad_to_deg, "deg")
        call echo_real(unit, "L2", dy%geom%l2, "m")
        call echo_real(unit, "L3", dy%geom%l3, "m")
        call echo_real(unit, "E", dy%geom%e, "m")
        call echo_array(unit, "SLOT_AT", dy%geom%slot_at, "m")
        call echo_real(unit, "SLOT_ANGLE", dy%geom%slot_angle * rad_to_deg, "deg")
        call echo_real(unit, "M2", lk(2 * d)%m, "kg")
        call echo_real(unit, "J2", lk(2 * d)%j, "kg*m^2")
        call echo_array(unit, "S2", lk(2 * d)%s, "m")
        call echo_real(unit, "M3", lk(2 * d + 1)%m, "kg")
        call echo_real(unit, "J3", lk(2 * d + 1)%j, "kg*m^2")
        call echo_array(unit, "S3", lk(2 * d + 1)%s, "m")
        call echo_real(unit, "FRAME_ANGLE", deck%pair_frame(3 * d) * rad_to_deg, "deg")
        call echo_int(unit, "INNER_ON", lk(merge(2 * d + 1, 2 * d, deck%pair_sign(3 * d - 1) < 0.0_wp))%id, "")
      end associate
    end do
    do k = 1, size(deck%mech%forces)
      associate (fo => deck%mech%forces(k))
        call echo_int(unit, "FORCE "//int_str(k)//" LINK", deck%mech%links(fo%link)%id, "")
        call echo_array(unit, "  AT", fo%at, "m")
        call echo_real(unit, "  ANGLE", fo%angle * rad_to_deg, "deg")
        call echo_logical(unit, "  FOLLOW", fo%follow, "")
        call echo_array(unit, "  VALUE", deck%f_mag(k, :), "N")
      end associate
    end do
    do k = 1, size(deck%mech%moment_link)
      call echo_int(unit, "MOMENT "//int_str(k)//" LINK", deck%mech%links(deck%mech%moment_link(k))%id, "")
      call echo_array(unit, "  VALUE", deck%m_mag(k, :), "N*m")
    end do

    call echo_heading(unit, "RESULTS")
    any_p = .false.
    do ip = 1, np
      any_p = any_p .or. assur_pair_prismatic(deck, ip)
    end do
    names = [(deck%pair_name(ip)(1:12), ip=1, np)]
    write (unit, header_fmt) "PHI1", (adjustr(names(ip)), ip=1, np), "M1"
    write (unit, header_fmt) "", (adjustr(trim(names(ip))//"G"), ip=1, np)
    if (any_p) then
      write (unit, header_fmt) "", (p_label(names(ip), "N", assur_pair_prismatic(deck, ip)), ip=1, np)
      write (unit, header_fmt) "", (p_label(names(ip), "M", assur_pair_prismatic(deck, ip)), ip=1, np)
    end if
    write (unit, header_fmt) "deg", (repeat(" ", 11)//"N", ip=1, np), "N*m"
    write (unit, header_fmt) "", (repeat(" ", 9)//"deg", ip=1, np)
    do k = 1, size(steps)
      v = assur_csv_values(deck, steps(k))
      pos = 1
      do ip = 1, np
        mag(ip) = v(pos + 1)
        ang(ip) = v(pos + 2)
        pos = pos + 2
        if (deck%components) pos = pos + 2
        nn(ip) = 0.0_wp
        mm(ip) = 0.0_wp
        if (assur_pair_prismatic(deck, ip)) then
          nn(ip) = v(pos + 1)
          mm(ip) = v(pos + 2)
          pos = pos + 2
        end if
      end do
      m1 = v(pos + 1)
      write (buf, phi_fmt) v(1)
      line1 = buf(1:9)
      do ip = 1, np
        line1 = line1//field12(mag(ip))
      end do
      write (unit, '(a)') line1//field12(m1)
      line2 = repeat(" ", 9)
      line3 = repeat(" ", 9)
      line4 = repeat(" ", 9)
      do ip = 1, np
        line2 = line2//field12(ang(ip))
        if (assur_pair_prismatic(deck, ip)) then
          line3 = line3//field12(nn(ip))
          line4 = line4//field12(mm(ip))
        else
          line3 = line3//repeat(" ", 12)
          line4 = line4//repeat(" ", 12)
        end if
      end do
      write (unit, '(a)') line2
      if (any_p) then
        write (unit, '(a)') trim(line3)
        write (unit, '(a)') trim(line4)
      end if
    end do
    call write_selfcheck_footer(unit, maxval(steps%residual), maxval(steps%mismatch), "M1")
  end subroutine write_assur_table

end module kinetostat_assur_report
