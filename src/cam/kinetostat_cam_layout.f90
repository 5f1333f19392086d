!> Cam follower as a mechanism of the run pipeline: deck -> every cam angle -> step table,
!> and its table layout (one line per step; flags in words).
module kinetostat_cam_layout
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, number_str, counted
  use kinetostat_vec2, only: magnitude, angle_360_deg
  use kinetostat_noise, only: noise_floor
  use kinetostat_run_tally, only: flag_count_t
  use kinetostat_step_table, only: step_table_t, column_t, column, col_input_angle, col_component, step_span, &
    col_length, col_flag, col_ratio, col_other, lack_block_memory
  use kinetostat_table_layout, only: table_field_t, field, force_and_angle, layout_columns, put_layout_heading, results_page_t, &
    echo_steps, put_fields
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_cam, only: cam_step_t, cam_step, cam_critical_angle, kf_limit
  use kinetostat_cam_deck, only: cam_deck_t, read_cam_deck, cam_template, follower_translating, &
    cam_phi_deg, cam_vdir, cam_x_b
  implicit none
  private
  public :: cam_mechanism_t, new_cam, cam_solve, cam_columns, cam_csv_values

  !> Forces with an angle column, in the order of the columns.
  character(*), parameter :: force_names(*) = [character(len=4) :: "F21", "F23C", "F23D"]
  !> Number of columns of a step's row (cam_columns).
  integer, parameter :: row_size = 16

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  CAM  FORCES ON A TRANSLATING FOLLOWER IN A GUIDE (MANUAL SECTION 7)", &
    title_ru = "KINETOSTAT  CAM  СИЛЫ В КУЛАЧКОВОМ МЕХАНИЗМЕ С" // &
      " ПОСТУПАТЕЛЬНО ДВИЖУЩИМСЯ ТОЛКАТЕЛЕМ (РАЗДЕЛ 7)"

  !> Cam with a translating (knife/roller) or flat follower in a guide, manual section 7.
  type, extends(mechanism_t) :: cam_mechanism_t
    !> The validated deck: cam, follower, guide and loads per cam angle.
    type(cam_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results, finish_run
  end type cam_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_cam(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (cam_mechanism_t :: mech)
    call mech%describe(cam_template, title_en, title_ru, "", &
      "Cam mechanism with a translating follower", &
      "Кулачковый механизм с поступательно движущимся толкателем")
  end subroutine new_cam

  subroutine load_deck(self, source, error)
    class(cam_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_cam_deck(source, self%deck, error)
  end subroutine load_deck

  !> All steps of a validated deck (in parallel with OpenMP threads).
  subroutine cam_solve(deck, steps, first, last, error)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> The results at the cam angles of steps first..last, one a step.
    type(cam_step_t), allocatable, intent(out) :: steps(:)
    !> Steps to compute (default: all).
    integer, intent(in), optional :: first, last
    !> The block's results do not fit in memory (exit 2).
    type(error_t), allocatable, intent(out), optional :: error
    integer :: k, k1, k2, stat
    call step_span(deck%n, k1, k2, first, last)
    allocate (steps(k2 - k1 + 1), stat=stat)
    if (stat /= 0) then
      if (present(error)) call lack_block_memory(error, k2 - k1 + 1, storage_size(steps, int64) / 8)
      return
    end if
    !$omp parallel do schedule(static)
    do k = k1, k2
      steps(k - k1 + 1) = cam_step(deck%p, deck%theta%at(k) * deg_to_rad, cam_x_b(deck, k), deck%mu_cam, &
                          deck%f2%at(k), cam_vdir(deck, k))
    end do
    !$omp end parallel do
  end subroutine cam_solve

  !> The block's cam angles into the step table; with the first block the columns, the
  !> INPUT DATA echo and the loads; the self-check of every step.
  subroutine solve(self, table, error)
    class(cam_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(cam_step_t), allocatable :: steps(:)
    integer :: k, first, last
    call table%block_range(self%deck%n, first, last)
    call cam_solve(self%deck, steps, first, last, error)
    if (allocated(error)) return
    if (table%first_block()) then
      call echo_deck(self%deck, table)
      ! a jammed or lost-contact step has no forces: empty in CSV, null in JSON, left out of
      ! the summary (docs/gears-cams.md)
      call table%declare_columns(cam_columns())
      table%input_column = 1
      table%void_flags = [table%column_index("JAM"), table%column_index("LOST")]
      table%void_reason = "jammed or lost contact"
      table%residual_label = "MAX EQUILIBRIUM RESIDUAL OF THE FOLLOWER, ALL STEPS"
      table%mismatch_label = "MAX N MISMATCH, CLOSED FORM VS 3X3 LINEAR SOLVE"
    end if
    call table%allocate_rows(size(steps), error)
    if (allocated(error)) return
    !$omp parallel do schedule(static)
    do k = 1, size(steps)
      table%rows(1:row_size, k) = cam_csv_values(self%deck, steps(k), first - 1 + k)
    end do
    !$omp end parallel do
    if (table%kinematics_wanted) then
      do k = 1, size(steps)
        call put_kinematics(table, k, self%deck, steps(k), first - 1 + k)
      end do
      ! the force components have no value at a void step either
      do k = row_size + 1, size(table%columns)
        if (index(table%columns(k)%name, "F2") == 1) table%columns(k)%voidable = .true.
      end do
    end if
    call table%set_selfcheck_rows([steps%residual], [steps%mismatch], "N")
    ! the steps jammed and those that lost contact, counted by the pipeline over the run
    table%block_tally%flags = [flagged([steps%jammed]), flagged([steps%lost])]
  contains
    !> How many of the block's steps a flag marks, and the first one's row of the run.
    pure function flagged(marks) result(f)
      logical, intent(in) :: marks(:)
      type(flag_count_t) :: f
      f%count = count(marks)
      if (f%count > 0) f%first_row = first - 1 + findloc(marks, .true., dim=1)
    end function flagged
  end subroutine solve

  !> Warnings for the steps whose forces the table shows as 0: a jammed (self-locking)
  !> follower and a lost contact, each with the number of such steps over the run and the
  !> first one.
  pure subroutine finish_run(self, table)
    class(cam_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    if (.not. allocated(table%run_tally%flags)) return
    call warn_flagged(self%deck, table%run_tally%flags(1), "the follower jams (self-locking: no finite contact force "// &
      "moves it)", table)
    call warn_flagged(self%deck, table%run_tally%flags(2), "contact is lost (F2 <= 0 does not hold the follower on "// &
      "the cam)", table)
  end subroutine finish_run

  !> The warning for the steps a flag counted over the run, when there are any.
  pure subroutine warn_flagged(deck, flags, what, table)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> Count and first flagged step.
    type(flag_count_t), intent(in) :: flags
    !> What happens at those steps.
    character(*), intent(in) :: what
    !> Where the warning goes.
    type(step_table_t), intent(inout) :: table
    integer :: first
    if (flags%count == 0) return
    first = flags%first_row
    call table%add_warning(what//" at "//counted(flags%count, "step")//", the first at step "//int_str(first)// &
      " (phi = "//number_str(cam_phi_deg(deck, first))//" deg); no forces there (empty in CSV, null in JSON, left out of"// &
      " the summary)")
  end subroutine warn_flagged

  !> The CSV row of step k (flags as 0/1; forces 0 when jammed or contact lost).
  pure function cam_csv_values(deck, s, k) result(v)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> One computed step.
    type(cam_step_t), intent(in) :: s
    !> Step number.
    integer, intent(in) :: k
    real(wp) :: v(row_size)
    v(1) = cam_phi_deg(deck, k)
    v(2) = deck%theta%at(k)
    v(3) = cam_x_b(deck, k)
    v(4) = deck%f2%at(k)
    v(5) = cam_vdir(deck, k)
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

  !> The kinematics columns of step `k` (frame: origin C, y along the follower's axis from C
  !> to D): the contact point B and the guide ends C, D, and the components of the forces
  !> F21, F23C, F23D. The deck gives no displacement law of the follower, so its position,
  !> velocity and acceleration are not computed.
  pure subroutine put_kinematics(table, k, deck, s, step)
    !> The step table (columns appended on first use).
    type(step_table_t), intent(inout) :: table
    !> Row.
    integer, intent(in) :: k
    !> The validated deck (the guide and the loads of each step).
    type(cam_deck_t), intent(in) :: deck
    !> The computed step.
    type(cam_step_t), intent(in) :: s
    !> Its step number (index of the deck's per-step values).
    integer, intent(in) :: step
    real(wp) :: f(2, 3), floor
    call table%put_point(k, "B", [cam_x_b(deck, step), -deck%p%a])
    call table%put_point(k, "C", [0.0_wp, 0.0_wp])
    call table%put_point(k, "D", [0.0_wp, deck%p%l])
    f = reshape([s%f21, s%f23c, s%f23d], [2, 3])
    floor = noise_floor(f, [real(wp) ::])
    call table%put_pair_components(k, force_names, f, floor)
  end subroutine put_kinematics

  !> The INPUT DATA echo of the deck.
  pure subroutine echo_deck(deck, table)
    type(cam_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    if (deck%follower == follower_translating) then
      call table%echo_text("FOLLOWER", "translating (knife/roller)")
    else
      call table%echo_text("FOLLOWER", "flat")
    end if
    call table%echo_real("L", deck%p%l, "m")
    call table%echo_real("L_OVER", deck%p%a, "m")
    call table%echo_real("F", deck%p%f, "")
    if (deck%follower /= follower_translating) then
      call table%echo_real("F_CAM", deck%f_cam, "")
      call table%echo_real("OMEGA_DIR", deck%omega_dir, "(+1 CCW, -1 CW)")
    end if
    call echo_steps(table, deck%phi_start, deck%dphi, deck%n)
    if (deck%follower == follower_translating) then
      call table%echo_array("THETA", deck%theta%as_given(deck%n), "deg")
    else
      call table%echo_array("DS_DPHI", deck%ds_dphi%as_given(deck%n), "m/rad")
    end if
    call table%echo_array("F2", deck%f2%as_given(deck%n), "N")
    if (deck%follower == follower_translating) then
      call table%echo_array("VDIR", deck%vdir%as_given(deck%n), "")
      call table%echo_real("THETA_CR", cam_critical_angle(deck%p) * rad_to_deg, "deg (rise; derived)")
    end if
    call table%echo_real("KF_LIMIT", kf_limit, "(Reshetov)")
  end subroutine echo_deck

  !> The columns of a step (one row per cam angle; docs/gears-cams.md "Cams: table and CSV"):
  !> the cam angle, the pressure angle, the follower's position, the load F2 and the motion's
  !> direction, the forces (no value at a jammed or lost-contact step), K_F and the flags; the
  !> flags field of RESULTS is headed on KF2.
  pure function cam_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    type(column_t) :: pair(2)
    integer :: j
    cols = [column("phi", "deg", col_input_angle, heading="PHI"), column("theta", "deg", col_other, heading="THETA"), &
            column("xB", "m", col_length, heading="XB"), column("F2", "N", col_component, heading="F2"), &
            column("vdir", "", col_flag, heading="V"), column("N", "N", col_component, voidable=.true.)]
    do j = 1, size(force_names)
      pair = force_and_angle(trim(force_names(j)))
      pair%voidable = .true.
      cols = [cols, pair]
    end do
    cols = [cols, column("KF", "", col_ratio, heading="KF", voidable=.true.), &
            column("KF2", "", col_flag, heading="FLAGS"), column("JAM", "", col_flag), column("LOST", "", col_flag)]
  end function cam_columns

  !> The RESULTS line of a step: the cam angle (8 wide), THETA, XB, F2, the direction V, the
  !> forces (13 wide) with their angles (8 wide), KF, then the flags field. (The units line
  !> gives V one place, not three: the forces' units stand two places left of their fields,
  !> as they always did.)
  pure function results_layout() result(fields)
    type(table_field_t), allocatable :: fields(:)
    integer :: j
    fields = [field("phi", 8, 2), field("theta", 8, 3), field("xB", 10, 5), field("F2", 11, 2), &
              field("vdir", 3, 0, whole=.true., unit_width=1)]
    do j = 1, size(force_names)
      fields = [fields, field(trim(force_names(j)), 13, 3), field(trim(force_names(j))//"G", 8, 2)]
    end do
    fields = [fields, field("KF", 10, 4), field("KF2", 7, 0)]
  end function results_layout

  !> The flag text of one row after two blanks, and the line's end: lost contact, jammed,
  !> or K_F over its limit. Appended piece by piece, not as a function's text of deferred
  !> length, whose length gfortran would keep in a static variable shared by the threads
  !> formatting blocks at once.
  pure subroutine put_flags(out, kf2, jam, lost, lang)
    type(text_buffer_t), intent(inout) :: out
    !> The row's flags KF2, JAM, LOST.
    real(wp), intent(in) :: kf2, jam, lost
    integer, intent(in) :: lang
    !> The flags LOST and JAM in words, in English (column 1) and Russian (column 2).
    character(*), parameter :: flag_words(2, 2) = reshape([character(len=60) :: &
      "LOST CONTACT (F2 <= 0)", "JAMMED (SELF-LOCKING)", &
      "ПОТЕРЯ КОНТАКТА (F2 <= 0)", "ЗАКЛИНИВАНИЕ (САМОТОРМОЖЕНИЕ)"], [2, 2])
    integer :: l
    l = merge(2, 1, lang == lang_ru)
    call out%append("  ")
    if (lost /= 0.0_wp) then
      call out%append(flag_words(1, l)(1:len_trim(flag_words(1, l))))
    else if (jam /= 0.0_wp) then
      call out%append(flag_words(2, l)(1:len_trim(flag_words(2, l))))
    else if (kf2 /= 0.0_wp) then
      call out%append("KF>2")
    end if
    call out%end_line()
  end subroutine put_flags

  !> RESULTS: one line per cam angle; a jammed or lost-contact step shows its flag instead
  !> of the forces.
  pure subroutine put_results(self, table, page, out, later)
    class(cam_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    integer, allocatable :: cols(:)
    type(table_field_t), allocatable :: fields(:)
    integer :: k, kf2, jam, lost
    allocate (fields(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    fields = results_layout()
    if (page%heading) call put_layout_heading(out, table, fields, page%lang, .true.)
    cols = layout_columns(table, fields)
    kf2 = table%column_index("KF2")
    jam = table%column_index("JAM")
    lost = table%column_index("LOST")
    do k = page%first, page%last
      associate (v => table%rows(:, k))
        ! a jammed or lost-contact step: its flag instead of the forces
        if (v(jam) == 0.0_wp .and. v(lost) == 0.0_wp) then
          call put_fields(out, v, fields, cols, 1, size(fields) - 1)
        else
          call put_fields(out, v, fields, cols, 1, 5)
        end if
        call put_flags(out, v(kf2), v(jam), v(lost), page%lang)
      end associate
    end do
  end subroutine put_results

end module kinetostat_cam_layout
