!> The generic engine as a mechanism of the run pipeline: `&assur` deck -> every step ->
!> step table (`phi1`, every pair, crank pin, `M1`), and its table layout (magnitudes /
!> angles / normal forces / reaction moments per step).
module kinetostat_assur_layout
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_noise, only: noise_rel
  use kinetostat_vec2, only: magnitude, angle_360_deg, angle_180_deg, rotate, snap_noise, clean_zero
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force, col_force_angle, col_component, &
    col_moment
  use kinetostat_format, only: fixed_field, display_width
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_assur_kinematics, only: kind_names
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_step_t, assur_step
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, write_assur_template
  implicit none
  private
  public :: assur_mechanism_t, new_assur, assur_solve, assur_csv_columns, assur_csv_values, assur_pair_prismatic

  !> Width of the PHI1 field of the RESULTS block.
  integer, parameter :: phi_width = 9
  !> Width of every other field of the RESULTS block.
  integer, parameter :: field_width = 12
  !> Dyad line of the INPUT DATA echo.
  character(*), parameter :: dyad_echo_fmt = '(3x,"DYAD ",i0,": ",a," LINKS ",i0,"-",i0,", ON LINKS ",i0," AND ",i0, &
    &", MODE ",i0)'

  !> A one-DOF linkage of class-II Assur groups on a crank (generic engine).
  type, extends(mechanism_t) :: assur_mechanism_t
    !> The validated deck.
    type(assur_deck_t) :: deck
  contains
    procedure :: read_deck
    procedure :: solve
    procedure :: write_results
    procedure :: write_template
  end type assur_mechanism_t

contains

  !> A new generic mechanism (the registry's constructor).
  subroutine new_assur(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (assur_mechanism_t :: mech)
    mech%title_en = "KINETOSTAT  ASSUR  FORCE ANALYSIS OF A LINKAGE OF CLASS-II ASSUR GROUPS"
    mech%title_ru = "KINETOSTAT  ASSUR  СИЛОВОЙ РАСЧЕТ МЕХАНИЗМА ИЗ ГРУПП АССУРА II" // &
      " КЛАССА"
  end subroutine new_assur

  subroutine read_deck(self, source, error)
    class(assur_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_assur_deck(source, self%deck, error)
  end subroutine read_deck

  pure subroutine write_template(self, out)
    class(assur_mechanism_t), intent(in) :: self
    type(text_buffer_t), intent(inout) :: out
    call write_assur_template(out)
  end subroutine write_template

  !> Every step into the step table, with the INPUT DATA echo and the self-check.
  subroutine solve(self, table, error)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(assur_step_t), allocatable :: steps(:)
    character(len=24), allocatable :: names(:)
    integer :: k, c, ip
    allocate (steps(0)) ! defined before the call (gcc's -Wmaybe-uninitialized on the descriptor)
    call assur_solve(table%deck, self%deck, steps, error)
    if (allocated(error)) return
    allocate (names(0))
    names = assur_csv_columns(self%deck)
    allocate (table%columns(0))
    call table%add_column("phi1", "deg", col_input_angle)
    c = 1
    do ip = 1, size(self%deck%pair_name)
      call table%add_column(trim(names(c + 1)), "N", col_force)
      call table%add_column(trim(names(c + 2)), "deg", col_force_angle)
      c = c + 2
      if (self%deck%components) then
        call table%add_column(trim(names(c + 1)), "N", col_component)
        call table%add_column(trim(names(c + 2)), "N", col_component)
        c = c + 2
      end if
      if (assur_pair_prismatic(self%deck, ip)) then
        call table%add_column(trim(names(c + 1)), "N", col_component)
        call table%add_column(trim(names(c + 2)), "N*m", col_moment)
        c = c + 2
      end if
    end do
    call table%add_column("M1", "N*m", col_moment)
    table%input_column = 1
    call table%allocate_rows(size(steps))
    do k = 1, size(steps)
      table%rows(:, k) = assur_csv_values(self%deck, steps(k))
    end do
    call table%set_selfcheck(maxval(steps%residual), maxval(steps%mismatch), "M1")
    do k = 1, size(self%deck%f_mag, 1)
      call table%note_load(self%deck%f_mag(k, :))
    end do
    do k = 1, size(self%deck%m_mag, 1)
      call table%note_load(self%deck%m_mag(k, :))
    end do
    if (len_trim(self%deck%title) > 0) table%subtitle = trim(self%deck%title)
    call echo_deck(self%deck, table)
  end subroutine solve

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

  !> A 12-wide right-adjusted header label `name//suffix`, blank when `show` is false.
  pure function p_label(name, suffix, show) result(label)
    character(*), intent(in) :: name, suffix
    logical, intent(in) :: show
    character(len=12) :: label
    label = ""
    if (show) label = adjustr(trim(name)//suffix)
  end function p_label

  !> The INPUT DATA echo of the deck (every deck value, dyad by dyad).
  pure subroutine echo_deck(deck, table)
    type(assur_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    character(len=160) :: line
    integer :: k, d
    call table%echo_int("FRAME_ID", deck%frame_id, "")
    call table%echo_int("CRANK_ID", deck%crank_id, "")
    call table%echo_array("CRANK_AT", deck%mech%pivot, "m")
    call table%echo_real("CRANK_M", deck%mech%links(1)%m, "kg")
    call table%echo_real("CRANK_J", deck%mech%links(1)%j, "kg*m^2")
    call table%echo_array("CRANK_S", deck%mech%links(1)%s, "m")
    if (deck%prescribed) then
      call table%echo_array("OMEGA1_STEP", deck%omega1, "rad/s")
      call table%echo_array("EPS1_STEP", deck%eps1, "rad/s^2")
    else
      call table%echo_real("OMEGA1", deck%omega1_const, "rad/s")
    end if
    call table%echo_real("G", deck%mech%g, "m/s^2")
    call table%echo_real("GRAVITY_ANGLE", deck%gravity_angle, "deg")
    call table%echo_real("PHI_START", deck%phi_start, "deg")
    call table%echo_real("DPHI", deck%dphi, "deg")
    call table%echo_int("N", deck%n, "steps")
    call table%echo_logical("ANGLES_SIGNED", deck%angles_signed, "")
    call table%echo_logical("COMPONENTS", deck%components, "")
    do d = 1, size(deck%mech%dyads)
      associate (dy => deck%mech%dyads(d), lk => deck%mech%links)
        write (line, dyad_echo_fmt) d, kind_names(dy%geom%kind), lk(2 * d)%id, lk(2 * d + 1)%id, &
          lk(dy%on(1))%id, lk(dy%on(2))%id, dy%geom%mode
        call table%echo_line(trim(line))
        call table%echo_array("AT2", dy%at(:, 1), "m")
        call table%echo_array("AT3", dy%at(:, 2), "m")
        call table%echo_real("ANGLE2", dy%ang(1) * rad_to_deg, "deg")
        call table%echo_real("ANGLE3", dy%ang(2) * rad_to_deg, "deg")
        call table%echo_real("L2", dy%geom%l2, "m")
        call table%echo_real("L3", dy%geom%l3, "m")
        call table%echo_real("E", dy%geom%e, "m")
        call table%echo_array("SLOT_AT", dy%geom%slot_at, "m")
        call table%echo_real("SLOT_ANGLE", dy%geom%slot_angle * rad_to_deg, "deg")
        call table%echo_real("M2", lk(2 * d)%m, "kg")
        call table%echo_real("J2", lk(2 * d)%j, "kg*m^2")
        call table%echo_array("S2", lk(2 * d)%s, "m")
        call table%echo_real("M3", lk(2 * d + 1)%m, "kg")
        call table%echo_real("J3", lk(2 * d + 1)%j, "kg*m^2")
        call table%echo_array("S3", lk(2 * d + 1)%s, "m")
        call table%echo_real("FRAME_ANGLE", deck%pair_frame(3 * d) * rad_to_deg, "deg")
        call table%echo_int("INNER_ON", lk(merge(2 * d + 1, 2 * d, deck%pair_sign(3 * d - 1) < 0.0_wp))%id, "")
      end associate
    end do
    do k = 1, size(deck%mech%forces)
      associate (fo => deck%mech%forces(k))
        call table%echo_int("FORCE "//int_str(k)//" LINK", deck%mech%links(fo%link)%id, "")
        call table%echo_array("  AT", fo%at, "m")
        call table%echo_real("  ANGLE", fo%angle * rad_to_deg, "deg")
        call table%echo_logical("  FOLLOW", fo%follow, "")
        call table%echo_array("  VALUE", deck%f_mag(k, :), "N")
      end associate
    end do
    do k = 1, size(deck%mech%moment_link)
      call table%echo_int("MOMENT "//int_str(k)//" LINK", deck%mech%links(deck%mech%moment_link(k))%id, "")
      call table%echo_array("  VALUE", deck%m_mag(k, :), "N*m")
    end do
  end subroutine echo_deck

  !> RESULTS: per step the crank angle, every pair's magnitude and M1; under them the angles;
  !> for prismatic pairs two more lines with the normal force and the reaction moment.
  pure subroutine write_results(self, table, lang, out)
    class(assur_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: out
    character(len=:), allocatable :: line1, line2, line3, line4
    character(len=field_width) :: name
    character(len=len(self%deck%pair_name)) :: full_name
    character(len=:), allocatable :: deg, newton, newton_m
    real(wp) :: mag, ang, nn, mm
    integer :: k, ip, np, pos
    logical :: any_p, prismatic

    np = size(self%deck%pair_name)
    any_p = .false.
    do ip = 1, np
      any_p = any_p .or. assur_pair_prismatic(self%deck, ip)
    end do
    if (lang == lang_ru) then
      deg = "град"
      newton = "Н"
      newton_m = "Н*м"
    else
      deg = "deg"
      newton = "N"
      newton_m = "N*m"
    end if
    line1 = adjustr(pad9("PHI1"))
    line2 = repeat(" ", phi_width)
    line3 = repeat(" ", phi_width)
    line4 = repeat(" ", phi_width)
    do ip = 1, np
      full_name = self%deck%pair_name(ip)
      name = full_name(1:field_width)
      prismatic = assur_pair_prismatic(self%deck, ip)
      line1 = line1//adjustr(name)
      line2 = line2//right(trim(name)//"G", field_width)
      line3 = line3//p_label(name, "N", prismatic)
      line4 = line4//p_label(name, "M", prismatic)
    end do
    call out%put(trim(line1//adjustr(pad12("M1"))))
    call out%put(trim(line2))
    if (any_p) then
      call out%put(line3)
      call out%put(line4)
    end if
    line1 = right(deg, phi_width)
    line2 = repeat(" ", phi_width)
    do ip = 1, np
      line1 = line1//right(newton, field_width)
      line2 = line2//right(deg, field_width)
    end do
    call out%put(trim(line1//right(newton_m, field_width)))
    call out%put(trim(line2))
    do k = 1, table%row_count()
      associate (v => table%rows(:, k))
        line1 = fixed_field(v(1), phi_width, 2)
        line2 = repeat(" ", phi_width)
        line3 = repeat(" ", phi_width)
        line4 = repeat(" ", phi_width)
        pos = 1
        do ip = 1, np
          mag = v(pos + 1)
          ang = v(pos + 2)
          pos = pos + 2
          if (self%deck%components) pos = pos + 2
          line1 = line1//fixed_field(mag, field_width, 2)
          line2 = line2//fixed_field(ang, field_width, 2)
          if (assur_pair_prismatic(self%deck, ip)) then
            nn = v(pos + 1)
            mm = v(pos + 2)
            pos = pos + 2
            line3 = line3//fixed_field(nn, field_width, 2)
            line4 = line4//fixed_field(mm, field_width, 2)
          else
            line3 = line3//repeat(" ", field_width)
            line4 = line4//repeat(" ", field_width)
          end if
        end do
        call out%put(line1//fixed_field(v(pos + 1), field_width, 2))
        call out%put(line2)
        if (any_p) then
          call out%put(trim(line3))
          call out%put(trim(line4))
        end if
      end associate
    end do
  end subroutine write_results

  !> `text` right-justified in `width` display characters.
  pure function right(text, width) result(field)
    character(*), intent(in) :: text
    integer, intent(in) :: width
    character(len=:), allocatable :: field
    field = repeat(" ", max(0, width - display_width(text)))//text
  end function right

  pure function pad9(text) result(field)
    character(*), intent(in) :: text
    character(len=phi_width) :: field
    field = text
  end function pad9

  pure function pad12(text) result(field)
    character(*), intent(in) :: text
    character(len=field_width) :: field
    field = text
  end function pad12

end module kinetostat_assur_layout
