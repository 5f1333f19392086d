!> The geometry of a spur gear pair as a mechanism of the run pipeline: deck -> the shifts
!> (given, chosen or split from a_w) -> one row of named values, the legacy block of named
!> values, the analysis deck (--format deck: a `&gears` stage) and the blocking contour as
!> CSV (`kinetostat contour`).
module kinetostat_gear_geometry_layout
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str, upper
  use kinetostat_step_table, only: step_table_t, column_t, column, col_length, col_ratio, col_other, col_flag
  use kinetostat_table_layout, only: results_page_t, heading_of, heading_unit_of, column_value, headed => named_column
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_table_writer, only: put_heading, value_line
  use kinetostat_format, only: full_number, int_field, pad_right, short_number
  use kinetostat_labels, only: lang_ru
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sheet, only: sheet_t
  use kinetostat_gear_sheet, only: draw_gear_sheet
  use kinetostat_gear_geometry, only: gear_pair_t, pair_geometry_t, contour_curve_t, pair_geometry, &
    involute, auto_shift, equal_sliding_split, blocking_contour, line_of_action
  use kinetostat_gear_geometry_deck, only: gear_geometry_deck_t, read_gear_geometry_deck, gear_geometry_template, &
    shift_auto, shift_from_x1, shift_from_x2
  implicit none
  private
  public :: gear_geometry_mechanism_t, new_gear_geometry, gear_geometry_solve, gear_geometry_columns
  public :: gear_contour_text

  !> Number of columns of the row (gear_geometry_columns).
  integer, parameter :: row_size = 31

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  GEAR_GEOMETRY  INVOLUTE SPUR GEAR PAIR WITH PROFILE SHIFT", &
    title_ru = "KINETOSTAT  GEAR_GEOMETRY  ГЕОМЕТРИЧЕСКИЙ РАСЧЕТ ЭВОЛЬВЕНТНОЙ"// &
      " ЗУБЧАТОЙ ПЕРЕДАЧИ СО СМЕЩЕНИЕМ"

  !> An external spur pair of involute gears with profile shift.
  type, extends(mechanism_t) :: gear_geometry_mechanism_t
    !> The validated deck: teeth, module, shifts.
    type(gear_geometry_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results, analysis_deck, design_sheet
  end type gear_geometry_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_gear_geometry(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (gear_geometry_mechanism_t :: mech)
    call mech%describe(gear_geometry_template, title_en, title_ru, "gears", &
      "Involute spur gear pair", &
      "Эвольвентная зубчатая передача")
  end subroutine new_gear_geometry

  subroutine load_deck(self, source, error)
    class(gear_geometry_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_gear_geometry_deck(source, self%deck, error)
  end subroutine load_deck

  !> The shifts of a validated deck (given, chosen, or split from a_w) and the geometry.
  pure subroutine gear_geometry_solve(deck, g, error)
    !> Validated deck.
    type(gear_geometry_deck_t), intent(in) :: deck
    !> The geometry of the pair.
    type(pair_geometry_t), intent(out) :: g
    !> No shifts meet the rule (shift = 'auto'), or the shifts give no working pressure angle.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: x1, x2
    x1 = deck%x1
    x2 = deck%x2
    if (deck%rule == shift_auto) then
      if (deck%has_a_w) then
        call equal_sliding_split(deck%pair, deck%x_sum, x1, x2, error)
      else
        call auto_shift(deck%pair, x1, x2, error)
      end if
      if (allocated(error)) return
    else if (deck%rule == shift_from_x1) then
      x2 = deck%x_sum - deck%x1
    else if (deck%rule == shift_from_x2) then
      x1 = deck%x_sum - deck%x2
    end if
    g = pair_geometry(deck%pair, x1, x2)
    if (.not. g%valid) then
      if (g%alpha_w > 0.0_wp) then
        call fatal_error(error, exit_input, "x1 = "//short_number(x1)//", x2 = "//short_number(x2)// &
          ": a tip circle lies inside its base circle (no involute flank); take larger shifts")
      else
        call fatal_error(error, exit_input, "x1 + x2 = "//short_number(x1 + x2)// &
          " is too negative: inv(alpha_w) <= 0, no working pressure angle")
      end if
    end if
  end subroutine gear_geometry_solve

  !> The row, the INPUT DATA echo, the self-check and a warning per flag.
  subroutine solve(self, table, error)
    class(gear_geometry_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(pair_geometry_t) :: g
    call gear_geometry_solve(self%deck, g, error)
    if (allocated(error)) then
      error%message = table%deck//": &"//table%mechanism//": "//error%message
      return
    end if
    call table%declare_record(gear_geometry_columns(), "pair", "eps_alpha")
    table%rows(:, 1) = row_values(g)
    table%residual_label = "INV(ALPHA_W) AGAINST ITS EQUATION"
    table%mismatch_label = "EPS_ALPHA: FORMULA VS THE PATH OF CONTACT'S ENDS"
    call table%set_selfcheck(involute_residual(self%deck%pair, g), path_mismatch(g), "eps_alpha", 1, 1)
    call echo_deck(self%deck, table)
    call flag_warnings(g, self%deck%pair, table)
  end subroutine solve

  !> The columns of the one row (docs/gear-geometry.md), each headed in RESULTS by its name
  !> in capitals: the shifts, the centre distance and working angle, the diameters and
  !> thicknesses of both gears (mm), the least shifts, eps_alpha, the specific slidings, then
  !> the blocking contour's flags (undercut, pointed teeth, interference of each gear).
  pure function gear_geometry_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    character(*), parameter :: lengths(*) = [character(len=3) :: "d", "db", "dw", "da", "df", "s", "sa"]
    character(*), parameter :: flags(*) = [character(len=12) :: "undercut", "pointed", "interference"]
    integer :: j, g
    cols = [headed("x1", "", col_ratio), headed("x2", "", col_ratio), headed("a_w", "mm", col_length), &
            headed("alpha_w", "deg", col_other), headed("y", "", col_ratio), headed("delta_y", "", col_ratio)]
    do j = 1, size(lengths)
      cols = [cols, headed(trim(lengths(j))//"1", "mm", col_length), headed(trim(lengths(j))//"2", "mm", col_length)]
    end do
    cols = [cols, headed("x1_min", "", col_ratio), headed("x2_min", "", col_ratio), headed("eps_alpha", "", col_ratio), &
            headed("lambda1", "", col_ratio), headed("lambda2", "", col_ratio)]
    do j = 1, size(flags)
      do g = 1, 2
        cols = [cols, headed(trim(flags(j))//achar(iachar("0") + g), "", col_flag)]
      end do
    end do
  end function gear_geometry_columns

  !> The output row of the geometry.
  pure function row_values(g) result(v)
    type(pair_geometry_t), intent(in) :: g
    real(wp) :: v(row_size)
    v(1:2) = g%x
    v(3) = g%a_w
    v(4) = g%alpha_w * rad_to_deg
    v(5) = g%y
    v(6) = g%delta_y
    v(7:8) = g%d
    v(9:10) = g%db
    v(11:12) = g%dw
    v(13:14) = g%da
    v(15:16) = g%df
    v(17:18) = g%s
    v(19:20) = g%sa
    v(21:22) = g%x_min
    v(23) = g%eps_alpha
    v(24:25) = g%sliding
    v(26:27) = merge(1.0_wp, 0.0_wp, g%undercut)
    v(28:29) = merge(1.0_wp, 0.0_wp, g%pointed)
    v(30:31) = merge(1.0_wp, 0.0_wp, g%interference)
  end function row_values

  !> Relative residual of inv(alpha_w) against inv(alpha) + 2 (x1 + x2) tan(alpha)/(z1 + z2).
  pure real(wp) function involute_residual(p, g)
    type(gear_pair_t), intent(in) :: p
    type(pair_geometry_t), intent(in) :: g
    real(wp) :: target
    target = involute(p%alpha) + 2.0_wp * sum(g%x) * tan(p%alpha) / real(p%z1 + p%z2, wp)
    involute_residual = abs(involute(g%alpha_w) - target) / target
  end function involute_residual

  !> eps_alpha again, from where the line of action crosses the two tip circles (solved as
  !> quadratics in the frame of line_of_action), relative to the formula's value.
  pure real(wp) function path_mismatch(g)
    type(pair_geometry_t), intent(in) :: g
    real(wp) :: pts(2, 5), u(2), o2(2), ra(2), b, c, t_near_n1, t_near_n2, eps
    pts = line_of_action(g)
    u = (pts(:, 2) - pts(:, 1)) / g%g
    o2 = [g%a_w, 0.0_wp]
    ra = 0.5_wp * g%da
    ! gear 2's tip circle: |N1 + t u - O2| = ra2, the root nearer N1
    b = dot_product(u, pts(:, 1) - o2)
    c = sum((pts(:, 1) - o2)**2) - ra(2)**2
    t_near_n1 = -b - sqrt(max(0.0_wp, b * b - c))
    ! gear 1's tip circle: |N1 + t u| = ra1, the root nearer N2
    b = dot_product(u, pts(:, 1))
    c = sum(pts(:, 1)**2) - ra(1)**2
    t_near_n2 = -b + sqrt(max(0.0_wp, b * b - c))
    eps = (t_near_n2 - t_near_n1) / g%base_pitch
    path_mismatch = abs(eps - g%eps_alpha) / max(abs(g%eps_alpha), 1.0e-300_wp)
  end function path_mismatch

  !> A warning for each condition of the blocking contour the pair breaks.
  pure subroutine flag_warnings(g, p, table)
    type(pair_geometry_t), intent(in) :: g
    type(gear_pair_t), intent(in) :: p
    type(step_table_t), intent(inout) :: table
    integer :: i
    character(len=1) :: n
    do i = 1, 2
      n = achar(iachar("0") + i)
      if (g%undercut(i)) call table%add_warning("gear "//n//" is undercut: x"//n//" = "//short_number(g%x(i))// &
        " < x"//n//"_min = "//short_number(g%x_min(i))//" (ha* - (z/2) sin^2 alpha)")
      if (g%pointed(i)) call table%add_warning("gear "//n//"'s tooth is too thin at the tip: sa"//n//" = "// &
        short_number(g%sa(i))//" mm < sa_min_star*m = "//short_number(p%sa_min_star * p%m)//" mm")
      if (g%interference(i)) call table%add_warning("interference: gear "//int_str(3 - i)// &
        "'s tip meshes below the base circle of gear "//n//" (the active path ends beyond N"//n//")")
    end do
    if (g%eps_alpha < 1.0_wp) call table%add_warning("eps_alpha = "//short_number(g%eps_alpha)// &
      " < 1: the pair does not keep a tooth in mesh at all times")
  end subroutine flag_warnings

  !> The INPUT DATA echo.
  pure subroutine echo_deck(deck, table)
    type(gear_geometry_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    call table%echo_real("M", deck%pair%m, "mm")
    call table%echo_int("Z1", deck%pair%z1, "")
    call table%echo_int("Z2", deck%pair%z2, "")
    call table%echo_real("ALPHA", deck%pair%alpha * rad_to_deg, "deg")
    call table%echo_real("HA_STAR", deck%pair%ha_star, "")
    call table%echo_real("C_STAR", deck%pair%c_star, "")
    call table%echo_real("SA_MIN_STAR", deck%pair%sa_min_star, "")
    select case (deck%rule)
    case (shift_auto)
      call table%echo_text("SHIFT", "auto")
    case (shift_from_x1)
      call table%echo_real("X1", deck%x1, "")
    case (shift_from_x2)
      call table%echo_real("X2", deck%x2, "")
    case default
      call table%echo_real("X1", deck%x1, "")
      call table%echo_real("X2", deck%x2, "")
    end select
    if (deck%has_a_w) then
      call table%echo_real("A_W", deck%a_w, "mm")
      call table%echo_real("X1 + X2", deck%x_sum, "(derived)")
    end if
    if (deck%has_m1) call table%echo_real("M1", deck%m1, "N*m")
  end subroutine echo_deck

  !> RESULTS: the named values of the pair, the flags in words.
  pure subroutine put_results(self, table, page, out, later)
    class(gear_geometry_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    integer :: c, lang
    ! one row: the run's only block
    if (page%first > 1 .or. page%last < 1) return
    lang = page%lang
    ! the values, then under their heading the blocking contour's flags in words
    do c = 1, size(table%columns)
      associate (col => table%columns(c))
        if (col%kind /= col_flag .and. .not. col%kinematic) then
          call out%put(value_line(heading_of(col, lang), table%rows(c, 1), heading_unit_of(col, lang)))
        end if
      end associate
    end do
    call put_heading(out, heading(lang))
    do c = 1, size(table%columns)
      associate (col => table%columns(c))
        if (col%kind == col_flag) then
          call out%put("   "//pad_right(heading_of(col, lang), 16)//"="//int_field(table%rows(c, 1), 18)//"  "// &
            flag_word(col%name, table%rows(c, 1) /= 0.0_wp, lang))
        end if
      end associate
    end do
  end subroutine put_results

  !> Heading of the conditions block.
  pure function heading(lang) result(text)
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    if (lang == lang_ru) then
      text = "ПРОВЕРКА ПО БЛОКИРУЮЩЕМУ КОНТУРУ (1 - УСЛОВИЕ НАРУШЕНО)"
    else
      text = "CONDITIONS OF THE BLOCKING CONTOUR (1 - BROKEN)"
    end if
  end function heading

  !> What flag column `name` (undercut1, pointed2, interference1, ...) means, in words
  !> (broken or kept).
  pure function flag_word(name, broken, lang) result(text)
    character(*), intent(in) :: name
    logical, intent(in) :: broken
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    !> The three flags (undercut, pointed teeth, interference) in English (column 1) and
    !> Russian (column 2), then the answers broken and kept.
    character(*), parameter :: words(3, 2) = reshape([character(len=60) :: &
      "UNDERCUT OF GEAR", "POINTED TEETH OF GEAR", "INTERFERENCE ON GEAR", &
      "ПОДРЕЗАНИЕ ЗУБЬЕВ КОЛЕСА", "ЗАОСТРЕНИЕ ЗУБЬЕВ КОЛЕСА", &
      "ИНТЕРФЕРЕНЦИЯ ЗУБЬЕВ КОЛЕСА"], [3, 2])
    character(*), parameter :: answers(2, 2) = reshape([character(len=10) :: &
      ": YES", ": NO", ": ЕСТЬ", ": НЕТ"], [2, 2])
    integer :: l, w
    l = merge(2, 1, lang == lang_ru)
    w = 3
    if (index(name, "undercut") == 1) w = 1
    if (index(name, "pointed") == 1) w = 2
    text = trim(words(w, l))//" "//name(len(name):)//trim(answers(merge(1, 2, broken), l))
  end function flag_word

  !> The matching analysis deck: a `&gears` spur stage of this pair (working pitch diameter
  !> dw1 and working pressure angle alpha_w), driven by the deck's m1.
  subroutine analysis_deck(self, table, out, error)
    class(gear_geometry_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    if (.not. self%deck%has_m1) then
      call fatal_error(error, exit_input, table%deck//": &gear_geometry: m1: missing: --format deck needs the "// &
        "torque on gear 1 (N*m) of the &gears deck it writes")
      return
    end if
    call out%put("! kinetostat deck: the forces in the mesh of the spur pair designed by a &gear_geometry")
    call out%put("! deck (kinetostat --format deck): z1 = "//int_str(self%deck%pair%z1)//", z2 = "// &
      int_str(self%deck%pair%z2)//", m = "//short_number(self%deck%pair%m)//" mm, x1 = "// &
      short_number(column_value(table, "x1", 1))// &
      ", x2 = "//short_number(column_value(table, "x2", 1))//", a_w = "// &
      short_number(column_value(table, "a_w", 1))//" mm.")
    call out%put("! The pitch diameter of the mesh is the working one (dw1), its angle alpha_w.")
    call out%put("&gears")
    call out%put("  stage   = 'spur'")
    call out%put("  m1      = "//full_number(self%deck%m1)//"   ! N*m, torque on gear 1 from its shaft")
    call out%put("  z1      = "//int_str(self%deck%pair%z1))
    call out%put("  z2      = "//int_str(self%deck%pair%z2))
    call out%put("  dw1     = "//full_number(column_value(table, "dw1", 1))//"   ! mm, working pitch diameter of gear 1")
    call out%put("  alpha_w = "//full_number(column_value(table, "alpha_w", 1))//"   ! deg, working pressure angle")
    call out%put("/")
  end subroutine analysis_deck

  !> The sheet of the pair (--format svg, dxf): the meshing drawing, the blocking contour with
  !> the pair's shifts marked, the dimensions (kinetostat_gear_sheet).
  subroutine design_sheet(self, table, lang, at_step, sheet, error)
    class(gear_geometry_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    integer, intent(in) :: at_step
    type(sheet_t), intent(out) :: sheet
    type(error_t), allocatable, intent(out) :: error
    call draw_gear_sheet(self%deck%pair, pair_geometry(self%deck%pair, column_value(table, "x1", 1), &
      column_value(table, "x2", 1)), table, &
      lang, sheet)
  end subroutine design_sheet

  !> `kinetostat contour DECK`: the blocking contour of the deck's pair (z1, z2 and the basic
  !> rack) as long-format CSV "curve,x1,x2", one point a line, the curves in the order of
  !> contour_names and each one's points in order along it.
  subroutine gear_contour_text(source, out, error)
    !> A `&gear_geometry` deck.
    type(deck_source_t), intent(in) :: source
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(gear_geometry_deck_t) :: deck
    type(contour_curve_t), allocatable :: curves(:)
    integer :: c, k
    call read_gear_geometry_deck(source, deck, error)
    if (allocated(error)) return
    allocate (curves(8))
    call blocking_contour(deck%pair, curves)
    call out%put("curve,x1,x2")
    do c = 1, size(curves)
      do k = 1, size(curves(c)%x1)
        call out%put(curves(c)%name//","//full_number(curves(c)%x1(k))//","//full_number(curves(c)%x2(k)))
      end do
    end do
  end subroutine gear_contour_text

end module kinetostat_gear_geometry_layout
