!> Gear meshes as a mechanism of the run pipeline: deck -> every stage -> step table (one
!> row per stage), and the table layout (one block of named values per stage).
module kinetostat_gears_layout
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_text, only: upper
  use kinetostat_noise, only: noise_rel
  use kinetostat_vec2, only: magnitude, angle_360_deg, snap_noise
  use kinetostat_step_table, only: step_table_t, column_t, column, col_count, col_length, col_ratio, col_moment, &
    col_component, col_force, col_force_angle
  use kinetostat_table_layout, only: results_page_t, forces_and_angles, heading_of, heading_unit_of, column_value
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_table_writer, only: put_heading, value_line
  use kinetostat_format, only: fixed_field
  use kinetostat_labels, only: label, phrase, echo_name, lang_ru
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_gears, only: gear_stage_t, gear_result_t, gear_pair, gear_series, gear_planetary_step, &
    gear_planetary, gear_bevel, gear_kind_names
  use kinetostat_gears_deck, only: gears_deck_t, read_gears_deck, gears_template, layout_series, layout_names
  implicit none
  private
  public :: gears_mechanism_t, new_gears, gears_solve, gears_columns, gears_csv_values

  !> In-plane forces with an angle column, in the order of the CSV columns.
  character(*), parameter :: force_names(*) = [character(len=3) :: "F12", "FS1", "FS2", "F23", "F2H"]

  !> Number of columns of a stage's row (gears_columns).
  integer, parameter :: row_size = 30
  !> Positions of the torque columns in a stage's row (M1, M2, M2P, M3, M3P).
  integer, parameter :: moment_columns(*) = [10, 11, 12, 29, 30]
  !> Width and decimals of a force angle in the RESULTS block (F11.4).
  integer, parameter :: angle_width = 11, angle_decimals = 4

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  GEARS  FORCES IN GEAR MESHES (MANUAL SECTION 6, FRICTION-FREE)", &
    title_ru = "KINETOSTAT  GEARS  СИЛЫ В ЗАЦЕПЛЕНИЯХ ЗУБЧАТЫХ" // &
      " КОЛЕС (РАЗДЕЛ 6, БЕЗ УЧЕТА ТРЕНИЯ)"

  !> Gear meshes: spur, helical, bevel, planetary stages, manual section 6.
  type, extends(mechanism_t) :: gears_mechanism_t
    !> The validated deck: the stages and their torques.
    type(gears_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results
  end type gears_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_gears(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (gears_mechanism_t :: mech)
    call mech%describe(gears_template, title_en, title_ru, "", &
      "Gear trains", &
      "Зубчатые механизмы")
  end subroutine new_gears

  subroutine load_deck(self, source, error)
    class(gears_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_gears_deck(source, self%deck, error)
  end subroutine load_deck

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

  !> A row of the step table per gear stage, the self-check of each and the INPUT DATA echo.
  subroutine solve(self, table, error)
    class(gears_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(gear_result_t), allocatable :: res(:)
    integer :: i
    call gears_solve(self%deck, res)
    call table%declare_columns(gears_columns())
    table%row_name = "stage"
    call table%allocate_rows(size(res), error)
    if (allocated(error)) return
    do i = 1, size(res)
      table%rows(:, i) = gears_csv_values(self%deck, res, i)
    end do
    if (table%kinematics_wanted) then
      do i = 1, size(res)
        call put_kinematics(table, i, res(i))
      end do
    end if
    call table%set_selfcheck_rows([res%residual], [res%mismatch], "M2")
    call echo_deck(self%deck, table)
  end subroutine solve

  !> The kinematics columns of stage `i` (statics only: no motion is computed): in the stage
  !> frame, the centres O1, O2 of gears 1 and 2 (planetary: sun and satellite 1) and the pitch
  !> point P of their mesh, and the components of the in-plane forces F12, FS1, FS2, F23, F2H
  !> as their angle columns give them.
  pure subroutine put_kinematics(table, i, r)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> Row (stage).
    integer, intent(in) :: i
    !> Results of the stage.
    type(gear_result_t), intent(in) :: r
    real(wp) :: f(2, 5), floor
    integer :: j
    call table%put_point(i, "O1", r%o1)
    call table%put_point(i, "O2", r%o2)
    call table%put_point(i, "P", r%p)
    f = reshape([r%f12, r%fs1, r%fs2, r%f23, r%f2h], [2, 5])
    floor = noise_rel * maxval([(magnitude(f(:, j)), j=1, 5)])
    call table%put_pair_components(i, force_names, f, floor)
  end subroutine put_kinematics

  !> The CSV row of stage `i`: diameters in mm, forces N (magnitude) and deg (angle).
  pure function gears_csv_values(deck, res, i) result(v)
    !> Validated deck.
    type(gears_deck_t), intent(in) :: deck
    !> Results of every stage.
    type(gear_result_t), intent(in) :: res(:)
    !> Stage number.
    integer, intent(in) :: i
    real(wp) :: v(row_size)
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

  !> The columns of a stage (one row per stage; docs/gears-cams.md "Gears: table and CSV"):
  !> its number, kind and teeth, the pitch diameters and ratio, the torques, the mesh's force
  !> components, the in-plane forces with their angles, the ring's torques. The RESULTS block
  !> names a value by its column's heading.
  pure function gears_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    cols = [column("stage", "", col_count), column("kind", "", col_count), column("z1", "", col_count), &
            column("z2", "", col_count), column("z3", "", col_count), column("k", "", col_count), &
            column("dw1", "mm", col_length), column("dw2", "mm", col_length, heading="DW2"), &
            column("u", "", col_ratio, heading="U"), column("M1", "N*m", col_moment, heading="M1"), &
            column("M2", "N*m", col_moment), column("M2P", "N*m", col_moment), &
            column("Ft", "N", col_component, heading="FT"), column("Fr1", "N", col_component, heading="FR1"), &
            column("Fa1", "N", col_component, heading="FA1"), column("Fr2", "N", col_component, heading="FR2"), &
            column("Fa2", "N", col_component, heading="FA2"), column("Fn", "N", col_component, heading="FN")]
    cols = [cols, forces_and_angles(force_names)]
    cols = [cols, column("M3", "N*m", col_moment), column("M3P", "N*m", col_moment)]
  end function gears_columns

  !> "STAGE i: KIND" (the stage heading of both blocks).
  pure function stage_heading(i, kind) result(text)
    integer, intent(in) :: i, kind
    character(len=:), allocatable :: text
    character(len=16) :: buf
    write (buf, '(i0)') i
    text = "STAGE "//trim(buf)//": "//trim(upper(gear_kind_names(kind)))
  end function stage_heading

  !> The INPUT DATA echo of the deck.
  pure subroutine echo_deck(deck, table)
    type(gears_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    type(gear_stage_t) :: st
    integer :: i
    call table%echo_text("LAYOUT", trim(layout_names(deck%layout)))
    call table%echo_int("STAGES", deck%n, "")
    do i = 1, deck%n
      st = deck%st(i)
      call table%echo_heading(stage_heading(i, st%kind))
      if (deck%layout /= layout_series .or. i == 1) call table%echo_real("M1", deck%m1(i), "N*m")
      call table%echo_int("Z1", st%z1, "")
      call table%echo_int("Z2", st%z2, "")
      if (st%kind == gear_planetary) then
        call table%echo_int("Z3", st%z3, "")
        call table%echo_int("K", st%k, "satellites")
      end if
      if (deck%module_mm(i) > 0.0_wp) call table%echo_real("M", deck%module_mm(i), "mm")
      call table%echo_real("DW1", st%dw1 * 1.0e3_wp, "mm")
      call table%echo_real("ALPHA_W", st%alpha_w * rad_to_deg, "deg")
      if (st%kind == gear_planetary) call table%echo_real("ALPHA_W23", st%alpha_w23 * rad_to_deg, "deg")
      if (st%kind == gear_bevel) call table%echo_real("DELTA1", st%delta1 * rad_to_deg, "deg (atan(z1/z2))")
      call table%echo_real("BETA", st%beta * rad_to_deg, "deg")
      call table%echo_real("GAMMA", st%gamma * rad_to_deg, "deg")
    end do
  end subroutine echo_deck

  !> A RESULTS line of a force: magnitude and angle.
  pure function vector_line(name, magnitude_n, angle_deg, lang) result(line)
    character(*), intent(in) :: name
    real(wp), intent(in) :: magnitude_n, angle_deg
    integer, intent(in) :: lang
    character(len=:), allocatable :: line
    character(len=angle_width) :: angle_text
    angle_text = fixed_field(angle_deg, angle_width, angle_decimals)
    if (lang == lang_ru) then
      line = value_line(name, magnitude_n, label("N", lang))//"   УГОЛ  ="//angle_text//"  "//label("deg", lang)
    else
      line = value_line(name, magnitude_n, "N")//"   ANGLE ="//angle_text//"  deg"
    end if
  end function vector_line

  !> RESULTS: a block per stage (the mesh's named values, force vectors, torques).
  pure subroutine put_results(self, table, page, out, later)
    class(gears_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    integer :: i, kind, c, lang
    lang = page%lang
    do i = page%first, page%last
      associate (v => table%rows(:, i))
        kind = nint(column_value(table, "kind", i))
        call put_heading(out, echo_name(stage_heading(i, kind), lang))
        ! the headed values, then the in-plane forces and the torques the stage's kind has
        do c = 1, size(table%columns)
          if (len(table%columns(c)%heading) == 0 .or. table%columns(c)%kind == col_force .or. &
              table%columns(c)%kind == col_force_angle) cycle
          call out%put(value_line(heading_of(table%columns(c), lang), v(c), heading_unit_of(table%columns(c), lang)))
        end do
        call out%put(force_line("F12"))
        call out%put(force_line("FS1"))
        if (kind /= gear_bevel) call out%put(force_line("FS2"))
        if (kind == gear_planetary) then
          call out%put(force_line("F23"))
          call out%put(force_line("F2H"))
          call out%put(value_line("M_H", column_value(table, "M2", i), phrase("N*m (carrier, from forces)", lang)))
          call out%put(value_line(echo_name("M_H POWER", lang), column_value(table, "M2P", i), &
                                  phrase("N*m (M1*u_1H)", lang)))
          call out%put(value_line(echo_name("M3 HOUSING", lang), column_value(table, "M3", i), &
                                  phrase("N*m (on the ring, from forces)", lang)))
          call out%put(value_line(echo_name("M3 BALANCE", lang), column_value(table, "M3P", i), &
                                  phrase("N*m (M1 - M_H)", lang)))
        else
          call out%put(value_line("M2", column_value(table, "M2", i), phrase("N*m (from forces)", lang)))
          call out%put(value_line(echo_name("M2 POWER", lang), column_value(table, "M2P", i), &
                                  phrase("N*m (power balance)", lang)))
        end if
      end associate
    end do
  contains
    !> The vector line of in-plane force `name` of stage i (magnitude and angle columns).
    pure function force_line(name) result(line)
      character(*), intent(in) :: name
      character(len=:), allocatable :: line
      line = vector_line(name, column_value(table, name, i), column_value(table, name//"G", i), lang)
    end function force_line
  end subroutine put_results


end module kinetostat_gears_layout
