!> The sheet of the mechanism at one step (`--format svg --at K`, `--format dxf --at K`), on
!> the drawing model: like a course-project force-plan sheet, on A4 portrait (A3 landscape when
!> the list of forces leaves the drawing too little room, or when A3 draws the mechanism at a
!> standard scale twice as large or larger), with the ГОСТ 2.301 frame and the title block
!> (Масштаб = the drawing's scale):
!> - the title, the deck and its title, the step with its input angle and the turn of the
!>   drawing ("gravity down the sheet");
!> - the mechanism at a ГОСТ 2.302 scale (kinetostat_mechanism_view) with every force of the
!>   step as an arrow at one round force scale μF (the longest about 28 mm);
!> - the length scale bar with μl (m/mm), the force scale bar with μF (N/mm), the legend of
!>   the force kinds;
!> - the list of every force (value and direction in the mechanism's position frame) and
!>   moment of the step, and a note naming the forces too short to draw (under 1 mm).
module kinetostat_mechanism_sheet
  use kinetostat_kinds, only: wp, rad_to_deg, version_string
  use kinetostat_text, only: int_str
  use kinetostat_format, only: short_number, fixed_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_scales, only: nice_step, round_scale, scale_number
  use kinetostat_typeset, only: typeset, runs_extent, char_count
  use kinetostat_sheet, only: sheet_t, paper_t, iso_paper, layer_text, layer_scales, anchor_start
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, block_height, block_width
  use kinetostat_drawing, only: drawing_t, force_kind_names
  use kinetostat_mechanism_view, only: mechanism_view_t, fit_mechanism_view, draw_mechanism, force_colours
  implicit none
  private
  public :: write_mechanism_sheet, fitted_size

  !> Room kept around the mechanism with its arrows for the labels, mm.
  real(wp), parameter :: arrow_room = 8.0_wp
  !> Length of the largest force arrow, mm (at most; more on a larger sheet).
  real(wp), parameter :: longest_arrow = 28.0_wp
  !> Font size of the list of forces (class "small"), mm; its rows' pitch.
  real(wp), parameter :: list_size = 2.4_wp, list_pitch = 3.6_wp
  !> Least height of the drawing's region on A4, mm.
  real(wp), parameter :: least_region = 110.0_wp

contains

  !> The sheet of the mechanism at row `k` of `table`, drawn from `drawing`, its words in
  !> language `lang`.
  pure subroutine write_mechanism_sheet(title, table, k, drawing, lang, sheet)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row drawn (1-based).
    integer, intent(in) :: k
    !> The mechanism at that row, with its forces.
    type(drawing_t), intent(in) :: drawing
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    character(len=128), allocatable :: texts(:)
    character(len=7), allocatable :: colours(:)
    type(paper_t) :: paper
    type(mechanism_view_t) :: view
    real(wp) :: fmax, mu_f, inner(4), region(4), list_box(4), bar_value, y, ratio(3), x
    character(len=:), allocatable :: line, short
    integer :: i, columns, rows, candidate, chosen
    !> The papers tried: A4 portrait, A3 portrait, A3 landscape.
    character(len=3), parameter :: candidates(3) = ["A4P", "A3P", "A3L"]

    call force_list(drawing, lang, texts, colours)
    fmax = 0.0_wp
    do i = 1, size(drawing%forces)
      fmax = max(fmax, hypot(drawing%forces(i)%f(1), drawing%forces(i)%f(2)))
    end do

    ! the paper: A4 portrait, unless A3 (portrait or landscape) draws the mechanism at a
    ! standard scale twice as large or more, or A4 leaves the drawing too little room
    mu_f = round_scale(fmax, longest_arrow)
    do candidate = 1, size(candidates)
      paper = iso_paper(candidates(candidate)(1:2), candidates(candidate)(3:3) == "L")
      call layout(paper, region, list_box, columns, rows)
      mu_f = force_scale_of(region)
      call fit_mechanism_view(drawing, region, arrow_room, view, force_scale=1.0_wp / mu_f)
      ratio(candidate) = view%drawing_scale%ratio
      if (candidate == 1 .and. region(4) - region(2) < least_region) ratio(candidate) = 0.0_wp
    end do
    chosen = 1
    if (max(ratio(2), ratio(3)) >= 2.0_wp * ratio(1) * (1.0_wp - 1.0e-9_wp)) chosen = merge(3, 2, ratio(3) > ratio(2))
    paper = iso_paper(candidates(chosen)(1:2), candidates(chosen)(3:3) == "L")
    call layout(paper, region, list_box, columns, rows)
    mu_f = force_scale_of(region)
    inner = paper%inside()
    call fit_mechanism_view(drawing, region, arrow_room, view, force_scale=1.0_wp / mu_f)

    call sheet%open(paper, lang, title//" - "//table%deck//" - "//table%row_name//" "//int_str(k), &
      "kinetostat --at "//int_str(k)//" sheet of "//table%deck//": the mechanism at "//view%drawing_scale%text// &
      " with every force of the step as an arrow (one force scale). The group of class mechanism gives the view: "// &
      "sheet point = data-origin + data-scale * (q1, -q2), q = the position turned by data-rotation (deg), mm.")
    call put_sheet_format(sheet, title_block_from_table(table, word("Mechanism with its forces", lang)//", "// &
      word(table%row_name, lang)//" "//int_str(k), view%drawing_scale%text))

    ! the header
    call sheet%set_layer(layer_text)
    call sheet%text(inner(1) + 5.0_wp, 12.0_wp, title, "title", size=fitted_size(title, 3.3_wp, &
      inner(3) - inner(1) - 10.0_wp, 0.8_wp), plain=.true.)
    line = word("deck", lang)//": "//table%deck
    if (allocated(table%subtitle)) line = line//"   "//table%subtitle
    call sheet%text(inner(1) + 5.0_wp, 17.5_wp, line, "subtitle", size=fitted_size(line, 3.0_wp, &
      inner(3) - inner(1) - 10.0_wp, 0.6_wp), plain=.true.)
    line = word(table%row_name, lang)//" "//int_str(k)//" "//word("of", lang)//" "//int_str(table%row_count())
    if (table%input_column > 0) line = line//": "//table%columns(table%input_column)%name//" = "// &
      short_number(table%rows(table%input_column, k))//" "//unit_word(table%columns(table%input_column)%unit, lang)
    if (allocated(drawing%view_note)) line = line//"; "//word(drawing%view_note, lang)
    line = line//"; "//version_string
    call sheet%text(inner(1) + 5.0_wp, 22.5_wp, line, "small")

    ! the mechanism
    call draw_mechanism(sheet, drawing, view, region, 1.0_wp / mu_f, short)

    ! scales and legend under the drawing
    call sheet%set_layer(layer_scales)
    y = region(4) + 6.0_wp
    bar_value = nice_step(40.0_wp / view%scale, 1, .false.)
    if (bar_value * view%scale > 45.0_wp) bar_value = bar_value / 2.0_wp
    call put_scale(sheet, region(1), y, bar_value * view%scale, word("lengths", lang)//": "// &
      short_number(bar_value)//" "//unit_word("m", lang)//";  μl = "//scale_number(view%mu_l())//" "// &
      unit_word("m", lang)//"/"//unit_word("mm", lang), x)
    if (fmax > 0.0_wp) then
      bar_value = nice_step(0.8_wp * fmax, 1, .false.)
      if (bar_value / mu_f > 40.0_wp) bar_value = bar_value / 2.0_wp
      call put_scale(sheet, region(1), y + 5.0_wp, bar_value / mu_f, word("forces", lang)//": "// &
        short_number(bar_value)//" "//unit_word("N", lang)//";  μF = "//scale_number(mu_f)//" "// &
        unit_word("N", lang)//"/"//unit_word("mm", lang), x)
    end if
    call sheet%set_layer(layer_text)
    do i = 1, size(force_colours)
      associate (tx => region(1) + 26.0_wp * (i - 1), ty => y + 10.0_wp)
        call sheet%line(tx, ty, tx + 5.0_wp, ty, stroke=force_colours(i), width=0.8_wp)
        call sheet%text(tx + 6.5_wp, ty + 0.9_wp, word(trim(force_kind_names(i)), lang), "small", plain=.true.)
      end associate
    end do

    ! the list of forces
    call sheet%text(list_box(1), list_box(2) + 2.5_wp, word("Forces of the step (angles counterclockwise from "// &
      "the x axis of the mechanism's frame)", lang), "label", bold=.true.)
    do i = 0, size(texts) - 1
      call sheet%text(list_box(1) + (list_box(3) - list_box(1)) / columns * modulo(i, columns), list_box(2) + 2.5_wp + &
        4.5_wp + list_pitch * (i / columns), trim(texts(i + 1)), "small", colour=colours(i + 1))
    end do
    if (len(short) > 0) call sheet%text(list_box(1), list_box(2) + 2.5_wp + 4.5_wp + list_pitch * rows, &
      word("not drawn, shorter than 1 mm at μF", lang)//": "//short, "note")
  contains
    !> μF (N per mm) in a region: the largest force about 28 mm long, or 15 % of the region's
    !> smaller side on a larger sheet.
    pure real(wp) function force_scale_of(region)
      real(wp), intent(in) :: region(4)
      force_scale_of = round_scale(fmax, max(longest_arrow, 0.15_wp * min(region(3) - region(1), region(4) - region(2))))
    end function force_scale_of
    !> The drawing's region and the list's box on `paper`: on a portrait sheet the list goes
    !> across under the drawing, above the title block; on a landscape one beside the title
    !> block, left of it (taller when it needs more room).
    pure subroutine layout(paper, region, list_box, columns, rows)
      type(paper_t), intent(in) :: paper
      real(wp), intent(out) :: region(4), list_box(4)
      integer, intent(out) :: columns, rows
      real(wp) :: b(4)
      b = paper%inside()
      if (paper%landscape) then
        list_box = [b(1) + 5.0_wp, b(4) - block_height + 1.0_wp, b(3) - block_width - 5.0_wp, b(4) - 1.0_wp]
        call list_layout(list_box(3) - list_box(1), texts, columns, rows)
        list_box(2) = min(list_box(2), list_box(4) - list_height(rows))
      else
        list_box = [b(1) + 5.0_wp, 0.0_wp, b(3) - 5.0_wp, b(4) - block_height - 3.0_wp]
        call list_layout(list_box(3) - list_box(1), texts, columns, rows)
        list_box(2) = list_box(4) - list_height(rows)
      end if
      region = [b(1) + 5.0_wp, 27.0_wp, b(3) - 5.0_wp, list_box(2) - 22.0_wp]
    end subroutine layout
    !> Height of the list of `n_rows` rows with its heading and the note line, mm.
    pure real(wp) function list_height(n_rows)
      integer, intent(in) :: n_rows
      list_height = 2.5_wp + 4.5_wp + list_pitch * n_rows + 1.0_wp
      if (len(short_note_names()) > 0) list_height = list_height + list_pitch
    end function list_height
    !> The forces too short to draw at μF (known before the drawing: |F| / μF < 1 mm).
    pure function short_note_names() result(names)
      character(len=:), allocatable :: names
      integer :: j
      names = ""
      do j = 1, size(drawing%forces)
        associate (f => drawing%forces(j))
          if (hypot(f%f(1), f%f(2)) > 0.0_wp .and. hypot(f%f(1), f%f(2)) / mu_f < 1.0_wp) names = names//trim(f%name)
        end associate
      end do
    end function short_note_names
  end subroutine write_mechanism_sheet

  !> Columns and rows of the list `texts` in `width` mm: up to four columns, as many as the
  !> widest entry allows.
  pure subroutine list_layout(width, texts, columns, rows)
    real(wp), intent(in) :: width
    character(*), intent(in) :: texts(:)
    integer, intent(out) :: columns, rows
    integer :: i, widest
    widest = 1
    do i = 1, size(texts)
      widest = max(widest, char_count(trim(texts(i))))
    end do
    columns = max(1, min(4, int(width / (0.6_wp * list_size * widest + 1.5_wp))))
    rows = (size(texts) + columns - 1) / columns
  end subroutine list_layout

  !> The forces and moments of the drawing as entries of the list (name, value, direction in
  !> the position frame), with their colours.
  pure subroutine force_list(drawing, lang, texts, colours)
    type(drawing_t), intent(in) :: drawing
    integer, intent(in) :: lang
    character(len=128), allocatable, intent(out) :: texts(:)
    character(len=7), allocatable, intent(out) :: colours(:)
    character(len=:), allocatable :: text
    real(wp) :: a
    integer :: i
    allocate (texts(0), colours(0))
    do i = 1, size(drawing%forces)
      associate (f => drawing%forces(i))
        a = modulo(atan2(f%f(2), f%f(1)) * rad_to_deg, 360.0_wp)
        if (a >= 359.95_wp) a = 0.0_wp
        text = trim(f%name)//" = "//short_number(hypot(f%f(1), f%f(2)))//" "//unit_word("N", lang)
        if (hypot(f%f(1), f%f(2)) > 0.0_wp) text = text//" "//word("at", lang)//" "//fixed_number(a, 1)//" "// &
          unit_word("deg", lang)
        texts = [character(len=128) :: texts, text]
        colours = [character(len=7) :: colours, force_colours(f%kind)]
      end associate
    end do
    do i = 1, size(drawing%moments)
      associate (m => drawing%moments(i))
        text = trim(m%name)//" = "//short_number(m%value)//" "//unit_word("N*m", lang)
        texts = [character(len=128) :: texts, text]
        colours = [character(len=7) :: colours, force_colours(m%kind)]
      end associate
    end do
  end subroutine force_list

  !> A scale bar of `length` mm at (x, y) with its label; `right` is where the label ends.
  pure subroutine put_scale(sheet, x, y, length, label, right)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y, length
    character(*), intent(in) :: label
    real(wp), intent(out) :: right
    real(wp) :: w, above, below
    call sheet%line(x, y, x + length, y, "scale")
    call sheet%line(x, y - 1.0_wp, x, y + 1.0_wp, "scale")
    call sheet%line(x + length, y - 1.0_wp, x + length, y + 1.0_wp, "scale")
    call sheet%text(x + length + 1.5_wp, y + 0.9_wp, label, "small")
    call runs_extent(typeset(label, sheet%lang), w, above, below)
    right = x + length + 1.5_wp + w * 2.4_wp
  end subroutine put_scale

  !> Font size of a line of `text` (class size `size`, mm) that fits `width` mm when a
  !> character is `factor` x the size wide: the class's size, or smaller (to 0.01 mm).
  pure real(wp) function fitted_size(text, size, width, factor)
    character(*), intent(in) :: text
    real(wp), intent(in) :: size, width, factor
    real(wp) :: w, above, below
    call runs_extent(typeset(text, 1), w, above, below)
    fitted_size = size
    if (w <= 0.0_wp) return
    fitted_size = min(size, floor(width / (w / 0.6_wp * factor) * 100.0_wp) / 100.0_wp)
  end function fitted_size


end module kinetostat_mechanism_sheet
