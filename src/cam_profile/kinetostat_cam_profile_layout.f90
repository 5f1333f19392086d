!> A disc cam's profile as a mechanism of the run pipeline: deck -> the cam's size -> one row
!> per cam angle (the law, the pressure angle, the radii of curvature, the pitch and actual
!> profiles), the size in the summary block, the table layout, and the analysis deck
!> (--format deck: the `&cam` deck of the follower's forces).
module kinetostat_cam_profile_layout
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_input, exit_usage
  use kinetostat_text, only: int_str, upper
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_length, col_other, step_span
  use kinetostat_table_layout, only: results_page_t, heading_of, heading_unit_of, headed => named_column
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_format, only: fixed_field, full_number, short_number, exp_field, pad_left
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sheet, only: sheet_t
  use kinetostat_cam_sheet, only: draw_cam_sheet, cam_sheet_step
  use kinetostat_cam_profile, only: cam_design_t, cam_point_t, cam_sizes_t, cam_point, motion_at, size_cam, &
    cam_extremes, segment_at, segment_limit, follower_flat, follower_roller, follower_oscillating, &
    follower_names, law_names, law_constant_velocity
  use kinetostat_cam_profile_deck, only: cam_profile_deck_t, read_cam_profile_deck, cam_profile_template
  implicit none
  private
  public :: cam_profile_mechanism_t, new_cam_profile, cam_profile_size, cam_profile_row

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  CAM_PROFILE  DISC CAM FOR A FOLLOWER'S LAW OF MOTION", &
    title_ru = "KINETOSTAT  CAM_PROFILE  ПРОФИЛИРОВАНИЕ ДИСКОВОГО КУЛАЧКА ПО ЗАКОНУ"// &
      " ДВИЖЕНИЯ ТОЛКАТЕЛЯ"

  !> A disc cam for a follower's law of motion.
  type, extends(mechanism_t) :: cam_profile_mechanism_t
    !> The validated deck: the follower's law of motion and the cam's limits.
    type(cam_profile_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results, analysis_deck, design_sheet
  end type cam_profile_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_cam_profile(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (cam_profile_mechanism_t :: mech)
    call mech%describe(cam_profile_template, title_en, title_ru, "cam", &
      "Disc cam mechanism", &
      "Кулачковый механизм с дисковым кулачком")
  end subroutine new_cam_profile

  subroutine load_deck(self, source, error)
    class(cam_profile_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_cam_profile_deck(source, self%deck, error)
  end subroutine load_deck

  !> The deck's cam, sized (r_prime, r_base set).
  pure subroutine cam_profile_size(deck, design, error)
    type(cam_profile_deck_t), intent(in) :: deck
    type(cam_design_t), intent(out) :: design
    type(error_t), allocatable, intent(out) :: error
    design = deck%design
    call size_cam(design, error)
  end subroutine cam_profile_size

  !> The output row of step k (cam angle (k - 1)*step): the law, velocity and acceleration,
  !> pressure angle (deg), radii of curvature and the two profiles; lengths m (an oscillating
  !> follower's s in deg, s' and s'' per rad, its speeds in rad/s and rad/s^2).
  pure function cam_profile_row(deck, design, k) result(v)
    type(cam_profile_deck_t), intent(in) :: deck
    type(cam_design_t), intent(in) :: design
    integer, intent(in) :: k
    real(wp), allocatable :: v(:)
    real(wp) :: phi, s, ds, d2s, w
    type(cam_point_t) :: p
    phi = real(k - 1, wp) * deck%step
    call motion_at(design, phi * deg_to_rad, s, ds, d2s)
    p = cam_point(design, phi * deg_to_rad, s, ds, d2s)
    w = abs(design%omega)
    if (design%follower == follower_oscillating) s = s * rad_to_deg
    v = [phi, s, ds, d2s, ds * w, d2s * w**2, p%theta * rad_to_deg, p%rho]
    if (design%follower /= follower_flat) v = [v, p%rho_pitch]
    v = [v, p%pitch, p%profile]
  end function cam_profile_row

  !> Every step into the step table, the size into its summary, the self-check, warnings.
  subroutine solve(self, table, error)
    class(cam_profile_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(cam_design_t) :: design
    type(cam_point_t) :: p
    real(wp) :: phi, s, ds, d2s, residual, mismatch, limit
    integer :: k, first, last, i
    call cam_profile_size(self%deck, design, error)
    if (allocated(error)) then
      error%message = table%deck//": &"//table%mechanism//": "//error%message
      return
    end if
    call table%block_range(self%deck%n, first, last)
    if (table%first_block()) then
      call table%declare_columns(cam_profile_columns(design))
      table%input_column = 1
      ! the SUMMARY block's extremes: the pressure angle (a roller) or the flat face's radius
      table%driver = "theta"
      if (design%follower == follower_flat) table%driver = "rho"
      table%residual_label = "THETA OVER ITS LIMIT (RELATIVE), ALL STEPS"
      if (design%follower == follower_flat) table%residual_label = "RHO BELOW RHO_MIN (RELATIVE), ALL STEPS"
      table%mismatch_label = "CURVATURE: TWO FORMULAS (X R_PRIME), ALL STEPS"
      call echo_deck(self%deck, table)
      call put_sizes(design, table)
      call warnings(design, table)
    end if
    call table%allocate_rows(last - first + 1)
    residual = 0.0_wp
    mismatch = 0.0_wp
    do k = first, last
      table%rows(:, k - first + 1) = cam_profile_row(self%deck, design, k)
      phi = real(k - 1, wp) * self%deck%step * deg_to_rad
      call motion_at(design, phi, s, ds, d2s)
      p = cam_point(design, phi, s, ds, d2s)
      i = segment_at(design, phi)
      if (design%follower == follower_flat) then
        residual = max(residual, (design%rho_min - p%rho) / design%rho_min)
      else
        limit = segment_limit(design, i)
        residual = max(residual, (abs(p%theta) - limit) / limit)
      end if
      ! the curvatures 1/rho (finite through an inflection, where rho is not) against the
      ! base circle's
      mismatch = max(mismatch, abs(1.0_wp / p%rho_pitch - 1.0_wp / p%rho_check) * design%r_prime)
    end do
    ! within the limit is no residual: the figure is how far beyond it a step goes
    residual = max(0.0_wp, residual)
    call table%set_selfcheck(residual, mismatch, table%driver, 0, 0)
  end subroutine solve

  !> The columns of the design's follower, each headed in RESULTS by its name in capitals:
  !> the cam angle, the follower's motion and its transfer functions (an oscillating
  !> follower's in deg and per rad), the pressure angle, the radius of curvature (and a
  !> roller's pitch curve's, rho_pitch), the pitch curve and the profile.
  pure function cam_profile_columns(design) result(cols)
    type(cam_design_t), intent(in) :: design
    type(column_t), allocatable :: cols(:)
    if (design%follower == follower_oscillating) then
      cols = [headed("phi", "deg", col_input_angle), headed("s", "deg", col_other), headed("ds", "", col_other), &
              headed("d2s", "1/rad", col_other), headed("v", "rad/s", col_other), headed("a", "rad/s^2", col_other)]
    else
      cols = [headed("phi", "deg", col_input_angle), headed("s", "m", col_length), headed("ds", "m/rad", col_other), &
              headed("d2s", "m/rad^2", col_other), headed("v", "m/s", col_other), headed("a", "m/s^2", col_other)]
    end if
    cols = [cols, headed("theta", "deg", col_other), headed("rho", "m", col_length)]
    if (design%follower /= follower_flat) cols = [cols, headed("rho_pitch", "m", col_length)]
    cols = [cols, headed("x_pitch", "m", col_length), headed("y_pitch", "m", col_length), &
            headed("x_profile", "m", col_length), headed("y_profile", "m", col_length)]
  end function cam_profile_columns

  !> The cam's size and extremes over the whole turn as the run's summary records.
  pure subroutine put_sizes(design, table)
    type(cam_design_t), intent(in) :: design
    type(step_table_t), intent(inout) :: table
    type(cam_sizes_t) :: x
    x = cam_extremes(design)
    table%summary_heading = "SIZE OF THE CAM"
    call table%summary_real("r_base", design%r_base, "m")
    if (design%follower == follower_flat) then
      call table%summary_real("face_width", x%face_width, "m")
      call table%summary_real("rho_min", x%rho_min, "m")
    else
      call table%summary_real("r_prime", design%r_prime, "m")
      if (design%follower == follower_oscillating) call table%summary_real("psi0", design%psi0 * rad_to_deg, "deg")
      call table%summary_real("theta_rise_max", x%theta_rise * rad_to_deg, "deg")
      call table%summary_real("theta_return_max", x%theta_return * rad_to_deg, "deg")
      if (x%rho_pitch_min < huge(1.0_wp)) call table%summary_real("rho_pitch_min", x%rho_pitch_min, "m")
      call table%summary_real("profile_undercut", merge(1.0_wp, 0.0_wp, x%rho_pitch_min <= design%roller_radius), "")
    end if
  end subroutine put_sizes

  !> Warnings: a roller larger than the pitch curve's least radius of curvature (the profile
  !> undercuts: the follower leaves the law), and the rigid impacts of a constant velocity.
  pure subroutine warnings(design, table)
    type(cam_design_t), intent(in) :: design
    type(step_table_t), intent(inout) :: table
    type(cam_sizes_t) :: x
    integer :: i
    if (design%follower /= follower_flat) then
      x = cam_extremes(design)
      if (x%rho_pitch_min <= design%roller_radius) call table%add_warning("the pitch curve's least radius of "// &
        "curvature "//short_number(x%rho_pitch_min)//" m is not larger than the roller ("// &
        short_number(design%roller_radius)//" m): the profile undercuts and the follower leaves its law; take "// &
        "a smaller roller or a larger cam")
    end if
    do i = 1, size(design%seg)
      if (design%seg(i)%law /= law_constant_velocity) cycle
      call table%add_warning("segment "//int_str(i)//" (constant_velocity): the velocity jumps at its ends, an "// &
        "infinite acceleration (rigid impact) and a corner of the profile there")
    end do
  end subroutine warnings

  !> The INPUT DATA echo.
  pure subroutine echo_deck(deck, table)
    type(cam_profile_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    integer :: i
    character(len=:), allocatable :: unit
    unit = "m"
    if (deck%design%follower == follower_oscillating) unit = "deg"
    call table%echo_text("FOLLOWER", trim(follower_names(deck%design%follower)))
    do i = 1, size(deck%design%seg)
      call table%echo_text("LAW("//int_str(i)//")", trim(law_names(deck%design%seg(i)%law)))
    end do
    call table%echo_array("BETA", deck%design%seg%beta * rad_to_deg, "deg")
    call table%echo_array("LIFT", deck%lift_given, unit)
    select case (deck%design%follower)
    case (follower_flat)
      call table%echo_real("RHO_MIN", deck%design%rho_min, "m")
    case default
      if (deck%design%follower == follower_roller) then
        call table%echo_real("OFFSET", deck%design%offset, "m")
      else
        call table%echo_real("ARM", deck%design%arm, "m")
        call table%echo_array("PIVOT", deck%design%pivot, "m")
      end if
      call table%echo_real("ROLLER_RADIUS", deck%design%roller_radius, "m")
      call table%echo_real("PRESSURE_ANGLE_MAX", deck%limit_rise_deg, "deg")
      call table%echo_real("PRESSURE_ANGLE_MAX_RETURN", deck%limit_return_deg, "deg")
    end select
    call table%echo_real("OMEGA", deck%design%omega, "rad/s")
    call table%echo_real("STEP", deck%step, "deg")
    if (deck%has_guide(1)) call table%echo_real("L", deck%l, "m")
    if (deck%has_guide(2)) call table%echo_real("L_OVER", deck%l_over, "m")
    if (deck%has_guide(3)) call table%echo_real("F", deck%f, "")
    if (deck%has_guide(4)) call table%echo_real("F2", deck%f2, "N")
    if (deck%has_f_cam) call table%echo_real("F_CAM", deck%f_cam, "")
  end subroutine echo_deck

  !> RESULTS: one line per cam angle.
  pure subroutine put_results(self, table, page, out, later)
    class(cam_profile_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    character(len=:), allocatable :: line
    integer :: k, c, nc, lang
    nc = size(table%columns)
    lang = page%lang
    if (page%heading) then
      ! the input's unit 5 places in, not right-aligned, as the table always had it
      line = pad_left(heading_of(table%columns(1), lang), 8)
      do c = 2, nc
        line = line//pad_left(heading_of(table%columns(c), lang), 13)
      end do
      call out%put(line)
      line = "     "//heading_unit_of(table%columns(1), lang)
      do c = 2, nc
        line = line//pad_left(heading_unit_of(table%columns(c), lang), 13)
      end do
      call out%put(line)
    end if
    do k = page%first, page%last
      associate (v => table%rows(:, k))
        line = fixed_field(v(1), 8, 2)
        do c = 2, nc
          line = line//" "//exp_field(v(c), 12, 5)
        end do
        call out%put(line)
      end associate
    end do
  end subroutine put_results

  !> The matching analysis deck: a `&cam` deck of the follower's forces at the same cam
  !> angles (translating roller: the pressure angle and the direction of motion per step;
  !> flat face: ds/dphi per step), with the deck's guide and load.
  subroutine analysis_deck(self, table, out, error)
    class(cam_profile_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: vdir(table%row_count()), tol
    type(cam_design_t) :: design
    integer :: n
    if (self%deck%design%follower == follower_oscillating) then
      call fatal_error(error, exit_usage, table%deck//": &cam_profile: --format deck: the force analysis (&cam) has "// &
        "translating followers only (roller or flat), not an oscillating one")
      return
    end if
    if (.not. all(self%deck%has_guide)) then
      call fatal_error(error, exit_input, table%deck//": &cam_profile: "//missing_names()//": missing: --format "// &
        "deck needs the guide (l, l_over, f) and the load f2 of the &cam deck it writes")
      return
    end if
    call cam_profile_size(self%deck, design, error)
    if (allocated(error)) return
    n = table%row_count()
    associate (ds => table%rows(table%column_index("ds"), 1:n), theta => table%rows(table%column_index("theta"), 1:n))
      tol = 1.0e-12_wp * maxval(abs(ds))
      vdir = 0.0_wp
      where (ds > tol) vdir = 1.0_wp
      where (ds < -tol) vdir = -1.0_wp
      call out%put("! kinetostat deck: the forces on the follower of the cam designed by a &cam_profile deck")
      call out%put("! (kinetostat --format deck): r_base = "//short_number(design%r_base)// &
        " m found there; the same cam angles.")
      call out%put("&cam")
      if (self%deck%design%follower == follower_flat) then
        call out%put("  follower  = 'flat'")
      else
        call out%put("  follower  = 'translating'")
      end if
      call out%put("  l         = "//full_number(self%deck%l)//"   ! m, guide length")
      call out%put("  l_over    = "//full_number(self%deck%l_over)//"   ! m, overhang of the contact point")
      call out%put("  f         = "//full_number(self%deck%f)//"   ! friction in the guide")
      call out%put("  phi_start = 0")
      call out%put("  dphi      = "//full_number(self%deck%step))
      call out%put("  n         = "//int_str(n))
      call out%put("  f2        = "//full_number(self%deck%f2)//"   ! N, load on the follower")
      if (self%deck%design%follower == follower_flat) then
        call out%put("  omega_dir = "//int_str(nint(sign(1.0_wp, self%deck%design%omega))))
        if (self%deck%has_f_cam) call out%put("  f_cam     = "//full_number(self%deck%f_cam))
        call put_list("ds_dphi", ds)
      else
        call put_list("theta", theta)
        call put_list("vdir", vdir)
      end if
      call out%put("/")
    end associate
  contains
    pure function missing_names() result(t)
      character(len=:), allocatable :: t
      character(len=6), parameter :: names(4) = [character(len=6) :: "l", "l_over", "f", "f2"]
      integer :: i
      t = ""
      do i = 1, 4
        if (self%deck%has_guide(i)) cycle
        if (len(t) > 0) t = t//", "
        t = t//trim(names(i))
      end do
    end function missing_names
    subroutine put_list(name, values)
      character(*), intent(in) :: name
      real(wp), intent(in) :: values(:)
      integer :: i, j
      character(len=:), allocatable :: line
      do i = 1, size(values), 5
        if (i == 1) then
          line = "  "//name//" = "
        else
          line = "    "
        end if
        do j = i, min(size(values), i + 4)
          line = line//full_number(values(j))
          if (j < size(values)) line = line//","
          if (j < min(size(values), i + 4)) line = line//" "
        end do
        call out%put(line)
      end do
    end subroutine put_list
  end subroutine analysis_deck

  !> The sheet of the cam (--format svg, dxf): the motion diagrams, the pressure angle, the
  !> profile with the follower at row --at K (else where the pressure angle is largest), the
  !> sizes (kinetostat_cam_sheet).
  subroutine design_sheet(self, table, lang, at_step, sheet, error)
    class(cam_profile_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    integer, intent(in) :: at_step
    type(sheet_t), intent(out) :: sheet
    type(error_t), allocatable, intent(out) :: error
    type(cam_design_t) :: design
    if (at_step > table%row_count()) then
      call fatal_error(error, exit_usage, "--at "//int_str(at_step)//": "//table%deck//" has "// &
        int_str(table%row_count())//" cam angles (1.."//int_str(table%row_count())//")")
      return
    end if
    call cam_profile_size(self%deck, design, error)
    if (allocated(error)) return
    call draw_cam_sheet(design, self%deck%step, table, lang, cam_sheet_step(design, table, at_step), sheet)
  end subroutine design_sheet

end module kinetostat_cam_profile_layout
