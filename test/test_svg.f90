!> Unit tests of the SVG sheets: number formatting of drawings, the SVG primitives, nice
!> ticks, the cycle mean, --pairs selection, and a small sheet whose hodograph path is
!> checked point by point against the forces it was drawn from.
module test_svg
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t, exit_usage
  use kinetostat_format, only: fixed_number, short_number
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force, col_force_angle, col_moment
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_labels, only: lang_en
  use kinetostat_svg, only: xml_escape, svg_line
  use kinetostat_run_sheet, only: write_run_sheet, pair_force_t, find_pair_forces, select_pair_forces, nice_step, &
    cycle_mean
  use kinetostat_sheet, only: sheet_t
  use kinetostat_sheet_svg, only: write_sheet_svg
  use kinetostat_labels, only: lang_ru
  use kinetostat_typeset, only: text_run_t, typeset, plain_text, run_base, run_sub, run_sup
  use kinetostat_scales, only: standard_drawing_scale, round_scale, drawing_scale_t
  use kinetostat_sheet, only: iso_paper, paper_t, entity_text, entity_line
  use kinetostat_sheet_dxf, only: write_sheet_dxf
  use kinetostat_label_place, only: segment_box_distance
  use test_harness, only: test_counts_t, check_true, check_close
  implicit none
  private
  public :: run_svg_tests

contains

  subroutine run_svg_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_numbers(t)
    call test_primitives(t)
    call test_ticks_and_mean(t)
    call test_pairs(t)
    call test_sheet(t)
    call test_typeset(t)
    call test_scales(t)
    call test_model(t)
  end subroutine run_svg_tests

  !> The runs of a label: their texts joined by "|" with the shift marked (_ lowered, ^ raised).
  pure function shown(runs) result(text)
    type(text_run_t), intent(in) :: runs(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, size(runs)
      if (i > 1) text = text//"|"
      select case (runs(i)%shift)
      case (run_sub)
        text = text//"_"
      case (run_sup)
        text = text//"^"
      case default
        continue
      end select
      text = text//runs(i)%text
    end do
  end function shown

  !> Label text into runs: the program's symbols typeset, words and paths as they are.
  subroutine test_typeset(t)
    type(test_counts_t), intent(inout) :: t
    type(text_run_t), allocatable :: runs(:)
    call check_text(t, "typeset F21 = 2043 N", "F|_21| = 2043 N", shown(typeset("F21 = 2043 N", lang_en)))
    call check_text(t, "typeset a_CB^τ", "a|_CB|^τ", shown(typeset("a_CB^τ", lang_en)))
    call check_text(t, "typeset a^k_B2B3", "a|^k|_B2B3", shown(typeset("a^k_B2B3", lang_en)))
    call check_text(t, "typeset v_B2B3", "v|_B2B3", shown(typeset("v_B2B3", lang_en)))
    call check_text(t, "typeset Phi2", "Φ|_2", shown(typeset("Phi2", lang_en)))
    call check_text(t, "typeset MPhi3 en", "M|_Φ3", shown(typeset("MPhi3", lang_en)))
    call check_text(t, "typeset MPhi3 ru", "M|_и3", shown(typeset("MPhi3", lang_ru)))
    call check_text(t, "typeset J_red ru", "J|_пр|, кг·м²", shown(typeset("J_red, кг*м^2", lang_ru)))
    call check_text(t, "typeset phi1, deg", "φ|_1|, deg", shown(typeset("phi1, deg", lang_en)))
    call check_text(t, "typeset phi3rel ru", "φ|_3отн", shown(typeset("phi3rel", lang_ru)))
    call check_text(t, "typeset dT, N*m", "ΔT, N·m", shown(typeset("dT, N*m", lang_en)))
    call check_text(t, "typeset two subscripts", "a|_J21,3|^n", shown(typeset("a_J21_3^n", lang_en)))
    call check_text(t, "typeset μv", "μ|_v| = 0.2", shown(typeset("μv = 0.2", lang_en)))
    call check_text(t, "typeset FS1, MQ1", "F|_S1| M|_Q1", shown(typeset("FS1 MQ1", lang_en)))
    call check_text(t, "typeset leaves words and paths", "deck: data/pr3207_flywheel.nml step 3 of 13", &
      shown(typeset("deck: data/pr3207_flywheel.nml step 3 of 13", lang_en)))
    call check_text(t, "typeset F_shake ru", "Φ|_гл", shown(typeset("F_shake", lang_ru)))
    call check_text(t, "plain_text (DXF)", "a_CB^τ F21", plain_text(typeset("a_CB^τ F21", lang_en)))
    allocate (runs(0)) ! defined before the assignment (gcc's -Wmaybe-uninitialized on the descriptor)
    runs = typeset("S2", lang_en)
    call check_true(t, "run shifts", size(runs) == 2 .and. all(runs%shift == [run_base, run_sub]), "S2: S on the "// &
      "baseline, 2 lowered")
  end subroutine test_typeset

  !> ГОСТ 2.302 drawing scales and round μ scales.
  subroutine test_scales(t)
    type(test_counts_t), intent(inout) :: t
    type(drawing_scale_t) :: s
    s = standard_drawing_scale(0.3_wp)
    call check_text(t, "drawing scale 0.3 -> 1:4", "1:4", s%text)
    s = standard_drawing_scale(0.19_wp)
    call check_text(t, "drawing scale 0.19 -> 1:10 (no 1:6 in the standard)", "1:10", s%text)
    s = standard_drawing_scale(0.45_wp)
    call check_text(t, "drawing scale 0.45 -> 1:2.5", "1:2.5", s%text)
    s = standard_drawing_scale(3.0_wp)
    call check_text(t, "drawing scale 3 -> 2.5:1", "2.5:1", s%text)
    s = standard_drawing_scale(1.0e-5_wp)
    call check_text(t, "drawing scale beyond the standard", "1:100000", s%text)
    call check_close(t, "round scale 2741 N over 28 mm", 100.0_wp, round_scale(2741.0_wp, 28.0_wp), 0.0_wp, 1.0e-12_wp)
    call check_close(t, "round scale 589 N over 28 mm", 25.0_wp, round_scale(589.0_wp, 28.0_wp), 0.0_wp, 1.0e-12_wp)
  end subroutine test_scales

  !> The model: paper sizes, a label placed off a line through its point, the DXF's text.
  subroutine test_model(t)
    type(test_counts_t), intent(inout) :: t
    type(sheet_t) :: sheet
    type(paper_t) :: paper
    type(text_buffer_t) :: out
    real(wp) :: tx, ty, b(4)
    character(len=:), allocatable :: dxf
    paper = iso_paper("A3", .true.)
    call check_true(t, "A3 landscape", paper%width == 420.0_wp .and. paper%height == 297.0_wp, "420 x 297 mm")
    paper = iso_paper("A1", .false.)
    call check_true(t, "A1 portrait", paper%width == 594.0_wp .and. paper%height == 841.0_wp, "594 x 841 mm")
    call sheet%open(iso_paper("A4", .false.), lang_en, "t", "d")
    ! lines through the point in four directions: the label must sit in a quadrant between them
    call sheet%line(50.0_wp, 100.0_wp, 150.0_wp, 100.0_wp, "link")
    call sheet%line(100.0_wp, 50.0_wp, 100.0_wp, 150.0_wp, "link")
    call sheet%place_label("S2", "label", 100.0_wp, 100.0_wp, 0.0_wp, [20.0_wp, 5.0_wp, 205.0_wp, 292.0_wp], tx=tx, ty=ty)
    ! the label's box (S: 2.8 mm, 2: 1.96 mm lowered 0.84): 0.6 * (2.8 + 1.96) wide
    b = [tx - 0.3_wp * (2.8_wp + 1.96_wp), ty - 0.8_wp * 2.8_wp, tx + 0.3_wp * (2.8_wp + 1.96_wp), ty + 0.84_wp + 0.392_wp]
    call check_true(t, "label off the lines", segment_box_distance([50.0_wp, 100.0_wp], [150.0_wp, 100.0_wp], b) > &
      0.25_wp .and. segment_box_distance([100.0_wp, 50.0_wp], [100.0_wp, 150.0_wp], b) > 0.25_wp, "box too near a line")
    call check_true(t, "label near its point", hypot(tx - 100.0_wp, ty - 100.0_wp) < 6.0_wp .and. sheet%leaders == 0, &
      "placed far away or with a leader")
    call check_true(t, "label is the last entity", sheet%items(sheet%count)%kind == entity_text .and. &
      sheet%items(1)%kind == entity_line, "entities out of order")
    call sheet%text(30.0_wp, 30.0_wp, "Phi2 = 5 Н", "num")
    call write_sheet_dxf(sheet, out)
    dxf = out%text()
    call check_true(t, "DXF text escaped as \U+XXXX", index(dxf, new_line("a")//"\U+03A62 = 5 \U+041D"//new_line("a")) &
      > 0, "no Φ2 = 5 Н as \U+03A62 = 5 \U+041D")
    call check_true(t, "DXF paper limits", index(dxf, "$LIMMAX"//new_line("a")//"10"//new_line("a")//"210.000000") > 0, &
      "no $LIMMAX 210")
  end subroutine test_model

  subroutine check_text(t, name, expected, computed)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name, expected, computed
    call check_true(t, name, expected == computed, "expected '"//expected//"', computed '"//computed//"'")
  end subroutine check_text

  subroutine test_numbers(t)
    type(test_counts_t), intent(inout) :: t
    call check_text(t, "fixed_number 2 decimals", "12.35", fixed_number(12.345678_wp, 2))
    call check_text(t, "fixed_number leading zero", "0.50", fixed_number(0.5_wp, 2))
    call check_text(t, "fixed_number negative leading zero", "-0.25", fixed_number(-0.25_wp, 2))
    call check_text(t, "fixed_number rounds to zero without sign", "0.00", fixed_number(-0.001_wp, 2))
    call check_text(t, "fixed_number 0 decimals", "-180", fixed_number(-180.0_wp, 0))
    call check_text(t, "fixed_number huge -> exponent", "1.000000000000E+020", fixed_number(1.0e20_wp, 2))
    call check_text(t, "short_number large", "2716", short_number(2716.428_wp))
    call check_text(t, "short_number tens", "35.3", short_number(35.31_wp))
    call check_text(t, "short_number small", "0.457", short_number(0.4567_wp))
    call check_text(t, "short_number zero", "0", short_number(0.0_wp))
    call check_text(t, "short_number 1e8", "1.23E+08", short_number(1.234e8_wp))
    ! a three-digit exponent keeps its E (not "1.00-300")
    call check_text(t, "short_number 1e-300 keeps its E", "1.00E-300", short_number(1.0e-300_wp))
    call check_text(t, "short_number -2.5e150 keeps its E", "-2.50E+150", short_number(-2.5e150_wp))
    call check_text(t, "short_number 1e-99 keeps its E", "1.00E-99", short_number(1.0e-99_wp))
  end subroutine test_numbers

  subroutine test_primitives(t)
    type(test_counts_t), intent(inout) :: t
    call check_text(t, "xml_escape", "a &amp; &lt;b&gt; &quot;c&quot; &apos;d&apos;", xml_escape("a & <b> ""c"" 'd'"))
    call check_text(t, "svg_line", '<line x1="1.00" y1="2.00" x2="3.50" y2="-4.00" class="axis"/>', &
      svg_line(1.0_wp, 2.0_wp, 3.5_wp, -4.0_wp, 'class="axis"'))
  end subroutine test_primitives

  subroutine test_ticks_and_mean(t)
    type(test_counts_t), intent(inout) :: t
    call check_close(t, "nice_step 6000/5", 2000.0_wp, nice_step(6000.0_wp, 5, .false.), 0.0_wp, 1.0e-9_wp)
    call check_close(t, "nice_step 0.7/5", 0.2_wp, nice_step(0.7_wp, 5, .false.), 0.0_wp, 1.0e-12_wp)
    call check_close(t, "nice_step 360 deg/6", 60.0_wp, nice_step(360.0_wp, 6, .true.), 0.0_wp, 1.0e-12_wp)
    call check_close(t, "nice_step 45 deg/6", 15.0_wp, nice_step(45.0_wp, 6, .true.), 0.0_wp, 1.0e-12_wp)
    ! trapezoidal mean: a linear ramp 0..10 over 0..360 has mean 5 whatever the spacing
    call check_close(t, "cycle_mean ramp", 5.0_wp, cycle_mean([0.0_wp, 60.0_wp, 360.0_wp], [0.0_wp, 10.0_wp / 6, &
      10.0_wp]), 1.0e-14_wp, 0.0_wp)
    call check_close(t, "cycle_mean one row", 3.0_wp, cycle_mean([10.0_wp], [3.0_wp]), 0.0_wp, 0.0_wp)
  end subroutine test_ticks_and_mean

  !> A table: phi1, F16, F16G, F21, F21G, M1 over 4 steps.
  subroutine small_table(table)
    type(step_table_t), intent(out) :: table
    integer :: k
    table%mechanism = "test"
    table%deck = "small<&>.nml"
    table%row_name = "step"
    call table%set_columns([character(len=4) :: "phi1", "F16", "F16G", "F21", "F21G", "M1"], &
      [character(len=3) :: "deg", "N", "deg", "N", "deg", "N*m"], &
      [col_input_angle, col_force, col_force_angle, col_force, col_force_angle, col_moment])
    table%input_column = 1
    table%driver = "M1"
    call table%allocate_rows(4)
    do k = 1, 4
      table%rows(:, k) = [90.0_wp * (k - 1), 100.0_wp * k, 30.0_wp * k, 50.0_wp, 180.0_wp, 10.0_wp * k]
    end do
  end subroutine small_table

  subroutine test_pairs(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(pair_force_t), allocatable :: all(:), chosen(:)
    type(error_t), allocatable :: error
    call small_table(table)
    call find_pair_forces(table, all)
    call check_true(t, "find_pair_forces", size(all) == 2, "expected F16 and F21")
    if (size(all) /= 2) return
    call check_text(t, "find_pair_forces names", "F16 F21", all(1)%name//" "//all(2)%name)
    call select_pair_forces(table, all, " f21 ", chosen, error)
    call check_true(t, "select_pair_forces any case", .not. allocated(error) .and. size(chosen) == 1, "F21 chosen")
    call select_pair_forces(table, all, "F16,F99", chosen, error)
    call check_true(t, "select_pair_forces unknown", allocated(error), "F99 must be an error")
    if (.not. allocated(error)) return
    call check_true(t, "select_pair_forces unknown is a usage error", error%code == exit_usage, error%message)
    call check_text(t, "select_pair_forces message", "--pairs: 'F99' is not a pair force of small<&>.nml " // &
      "(pair forces: F16, F21)", error%message)
  end subroutine test_pairs

  !> The sheet of the small table: the F16 path read back (origin and scale from its
  !> attributes) equals F16's components within the 0.005 mm rounding of the coordinates.
  subroutine test_sheet(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    type(sheet_t) :: sheet
    type(error_t), allocatable :: error
    character(len=:), allocatable :: s, d
    real(wp) :: ox, oy, scale, x, y, fx, fy
    integer :: i, j, k, ios
    scale = 0.0_wp
    ox = 0.0_wp
    oy = 0.0_wp
    call small_table(table)
    call write_run_sheet("TEST", table, "", lang_en, sheet, error)
    call check_true(t, "write_run_sheet runs", .not. allocated(error), "no error expected")
    if (allocated(error)) return
    call write_sheet_svg(sheet, out)
    s = out%text()
    call check_true(t, "sheet escapes the deck name", index(s, "small&lt;&amp;&gt;.nml") > 0 .and. &
      index(s, "small<&>") == 0, "deck name not escaped")
    call check_true(t, "sheet has the mean", index(s, "mean 25.0 N·m") > 0, &
      "mean of M1 = 10, 20, 30, 40 over 0..270 deg (trapezoid) = 25")
    i = index(s, 'data-force="F16"')
    call check_true(t, "sheet has the F16 hodograph", i > 0, "no F16 path")
    if (i == 0) return
    j = index(s(i:), 'data-origin="') + i + 12
    read (s(j:j + index(s(j:), '"') - 2), *, iostat=ios) ox, oy
    call check_true(t, "F16 data-origin reads", ios == 0, s(j:j + 20))
    j = index(s(i:), 'data-scale="') + i + 11
    read (s(j:j + index(s(j:), '"') - 2), *, iostat=ios) scale
    call check_true(t, "F16 data-scale reads", ios == 0 .and. scale > 0.0_wp, s(j:j + 20))
    if (scale <= 0.0_wp) return
    j = index(s(1:i), '<path d="', back=.true.) + 9
    d = s(j:j + index(s(j:), '"') - 2)
    do k = 1, 4
      j = scan(d, "ML")
      d = d(j + 1:)
      read (d, *, iostat=ios) x, y
      call check_true(t, "F16 path point reads", ios == 0, d(1:min(len(d), 30)))
      fx = (x - ox) / scale
      fy = (oy - y) / scale
      call check_close(t, "F16 path x, step", 100.0_wp * k * cos(30.0_wp * k * deg_to_rad), fx, 0.0_wp, &
        0.0051_wp / scale)
      call check_close(t, "F16 path y, step", 100.0_wp * k * sin(30.0_wp * k * deg_to_rad), fy, 0.0_wp, &
        0.0051_wp / scale)
    end do
    call check_true(t, "sheet ends", s(len(s) - 6:) == "</svg>"//new_line("a"), "no closing tag")
  end subroutine test_sheet

end module test_svg
