!> The format of a sheet on the drawing model: the ГОСТ 2.301 frame (20 mm from the left
!> edge, 5 mm from the others) and the main inscription of ГОСТ 2.104, form 1, 185 x 55 mm, in
!> the frame's lower right corner, in the sheet's language:
!> - left, 65 mm: the grid of changes (rows of 5 mm; columns Изм. 7, Лист 10, № докум. 23,
!>   Подп. 15, Дата 10 mm) and the signatures Разраб. (the student and the date of the run,
!>   with --student), Пров., Т.контр., Н.контр., Утв.;
!> - right, 120 mm: the designation (графа 2, 120 x 15: empty unless one is given), the
!>   drawing's name (графа 1, 70 x 25: a long name is written smaller, then on two lines),
!>   the letter (У, a student's drawing), Масса, Масштаб (the drawing's scale, "1:5", when the
!>   sheet has one), Лист N, Листов M (50 x 25); the program and the run's time (70 x 15);
!>   the organisation field with the group and the variant (50 x 15).
!> Drawn on layer FRAME with the classes "border" (the frame), "thick" (0.5 mm) and "thin"
!> (0.18 mm). `put_title_block` keeps the older entry point of sheets not yet on the model
!> (a block under a sheet made title_block_height taller), drawn through the same code.
module kinetostat_title_block
  use kinetostat_kinds, only: wp, version_string
  use kinetostat_step_table, only: step_table_t, student_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_text, only: int_str
  use kinetostat_labels, only: lang_ru, label, in_language
  use kinetostat_typeset, only: char_count
  use kinetostat_sheet, only: sheet_t, paper_t, layer_frame, anchor_middle, frame_left, frame_margin, line_classes
  use kinetostat_sheet_svg, only: put_sheet_elements
  implicit none
  private
  public :: title_block_t, title_block_from_table, put_sheet_format, put_title_block_at, put_title_block, &
    title_block_height, block_width, block_height, fitted_text, header_indent, deck_line, course_title, course_data_line

  !> Size of the block (ГОСТ 2.104 form 1), mm.
  real(wp), parameter :: block_width = 185.0_wp, block_height = 55.0_wp
  !> Height a sheet not on a standard format grows by to carry the block (the block and the
  !> 5 mm margin below it), mm.
  real(wp), parameter :: title_block_height = block_height + 5.0_wp
  !> Font size of the entries, mm.
  real(wp), parameter :: entry_size = 2.4_wp

  !> What the title block says.
  type :: title_block_t
    !> The drawing's name (графа 1), in the sheet's language.
    character(len=:), allocatable :: drawing_name
    !> The document's designation (графа 2); "" leaves it empty.
    character(len=:), allocatable :: designation
    !> The drawing's scale ("1:5"), "" when the sheet has none.
    character(len=:), allocatable :: scale
    !> The student (Разраб.), the group and variant (organisation field), the run's date
    !> and time ("25.11.2026 18:31"); each "" without --student.
    type(student_t) :: student
    !> Лист, Листов.
    integer :: sheet_number = 1, sheet_count = 1
  end type title_block_t

contains

  !> The title block of a run's sheet: the student's fields from the table (--student), the
  !> drawing's name and scale given.
  pure function title_block_from_table(table, drawing_name, scale) result(block)
    !> The results (their student's header).
    type(step_table_t), intent(in) :: table
    !> The drawing's name, in the sheet's language.
    character(*), intent(in) :: drawing_name
    !> The drawing's scale ("1:5"), or "".
    character(*), intent(in) :: scale
    type(title_block_t) :: block
    block%drawing_name = drawing_name
    block%designation = ""
    block%scale = scale
    block%student = student_t("", "", "", "")
    if (allocated(table%designation)) block%designation = table%designation
    block%sheet_number = table%sheet_number
    block%sheet_count = table%sheet_count
    if (allocated(table%student)) block%student = table%student
  end function title_block_from_table

  !> How far a sheet's header starts right of the frame: past графа 26 (70 mm) when the
  !> sheet has a designation, mm.
  pure real(wp) function header_indent(table)
    type(step_table_t), intent(in) :: table
    header_indent = 0.0_wp
    if (.not. allocated(table%designation)) return
    if (len(table%designation) > 0) header_indent = 72.0_wp
  end function header_indent

  !> A sheet's header line of the run: the deck, its own title and the --set changes (the
  !> user's words: written plain).
  pure function deck_line(table, lang) result(line)
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(len=:), allocatable :: line
    line = label("deck", lang)//": "//table%deck
    if (allocated(table%subtitle)) line = line//"   "//table%subtitle
    if (len(set_changes(table)) > 0) line = line//"   --set"//set_changes(table)
  end function deck_line

  !> The run's --set changes, each after a blank (" l_ab=0.12 dphi=1"); "" when none.
  pure function set_changes(table) result(text)
    type(step_table_t), intent(in) :: table
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    if (.not. allocated(table%overrides)) return
    do i = 1, size(table%overrides)
      text = text//" "//trim(table%overrides(i))
    end do
  end function set_changes

  !> The mechanism's name on a course sheet: the kind's title line without the program's
  !> name and kind ("KINETOSTAT  PR 3207  СИЛОВОЙ РАСЧЕТ ..." -> "СИЛОВОЙ РАСЧЕТ ..."), in the
  !> sheet's language.
  pure function course_title(title) result(text)
    !> The kind's title line (mechanism_t%title).
    character(*), intent(in) :: title
    character(len=:), allocatable :: text
    character(*), parameter :: program = "KINETOSTAT  "
    integer :: k
    text = trim(title)
    if (index(text, program) /= 1) return
    k = index(text(len(program) + 1:), "  ")
    if (k == 0) return
    text = trim(adjustl(text(len(program) + k:)))
  end function course_title

  !> A course sheet's line under the mechanism's name: the deck's own title and the --set
  !> changes of the run (the user's words, written plain), and no file: the sheet is handed
  !> in, its data is the mechanism, not where it was kept ("механизм: TITLE;  изменения
  !> данных: l_ab=0.12"); "" when the deck has neither.
  pure function course_data_line(table, lang) result(line)
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: line
    line = ""
    if (allocated(table%subtitle)) then
      if (len_trim(table%subtitle) > 0) line = in_language("mechanism: ", "механизм: ", lang)//trim(table%subtitle)
    end if
    if (len(set_changes(table)) == 0) return
    if (len(line) > 0) line = line//";  "
    line = line//in_language("data changed:", "изменения данных:", lang)//set_changes(table)
  end function course_data_line

  !> The frame of the sheet's paper and the title block in its lower right corner.
  pure subroutine put_sheet_format(sheet, block)
    type(sheet_t), intent(inout) :: sheet
    type(title_block_t), intent(in) :: block
    real(wp) :: w, h
    w = sheet%paper%width
    h = sheet%paper%height
    call sheet%set_layer(layer_frame)
    call sheet%rect(frame_left, frame_margin, w - frame_left - frame_margin, h - 2.0_wp * frame_margin, "border")
    call put_title_block_at(sheet, block, w - frame_margin - block_width, h - frame_margin - block_height)
    if (.not. allocated(block%designation)) return
    if (len(block%designation) == 0) return
    ! графа 26: the designation again, turned 180 deg, in a 70 x 14 mm box in the frame's upper
    ! left corner (read when the sheet is folded or turned over)
    call sheet%rect(frame_left, frame_margin, 70.0_wp, 14.0_wp, "thick")
    call sheet%text(frame_left + 35.0_wp, frame_margin + 7.0_wp - 1.2_wp, fitted_text(block%designation, 66.0_wp, &
      3.5_wp), "cell", anchor_middle, size=3.5_wp, rotation=180.0_wp, plain=.true.)
  end subroutine put_sheet_format

  !> The title block with its upper left corner at (x0, y0), mm.
  pure subroutine put_title_block_at(sheet, block, x0, y0)
    type(sheet_t), intent(inout) :: sheet
    type(title_block_t), intent(in) :: block
    real(wp), intent(in) :: x0, y0
    real(wp) :: x, size
    integer :: i
    real(wp), parameter :: left_columns(5) = [7.0_wp, 10.0_wp, 23.0_wp, 15.0_wp, 10.0_wp]
    character(len=:), allocatable :: date, name
    call sheet%set_layer(layer_frame)
    ! the frame and the thick lines
    call sheet%rect(x0, y0, block_width, block_height, "thick", fill="#ffffff")
    call sheet%line(x0 + 65.0_wp, y0, x0 + 65.0_wp, y0 + block_height, "thick")
    call sheet%line(x0 + 65.0_wp, y0 + 15.0_wp, x0 + block_width, y0 + 15.0_wp, "thick")
    call sheet%line(x0 + 65.0_wp, y0 + 40.0_wp, x0 + block_width, y0 + 40.0_wp, "thick")
    call sheet%line(x0 + 135.0_wp, y0 + 15.0_wp, x0 + 135.0_wp, y0 + block_height, "thick")
    call sheet%line(x0, y0 + 25.0_wp, x0 + 65.0_wp, y0 + 25.0_wp, "thick")
    call sheet%line(x0, y0 + 20.0_wp, x0 + 65.0_wp, y0 + 20.0_wp, "thick")
    ! the left part: rows of 5 mm; the columns over the changes' rows, two over the signatures
    do i = 1, 10
      if (i == 4 .or. i == 5) cycle
      call sheet%line(x0, y0 + 5.0_wp * i, x0 + 65.0_wp, y0 + 5.0_wp * i, "thin")
    end do
    x = x0
    do i = 1, 4
      x = x + left_columns(i)
      if (i == 1) then
        call sheet%line(x, y0, x, y0 + 25.0_wp, "thick")
      else
        call sheet%line(x, y0, x, y0 + block_height, "thick")
      end if
    end do
    ! the right part: letter, mass, scale; sheet, sheets
    call sheet%line(x0 + 135.0_wp, y0 + 20.0_wp, x0 + block_width, y0 + 20.0_wp, "thin")
    call sheet%line(x0 + 135.0_wp, y0 + 35.0_wp, x0 + block_width, y0 + 35.0_wp, "thin")
    call sheet%line(x0 + 150.0_wp, y0 + 15.0_wp, x0 + 150.0_wp, y0 + 35.0_wp, "thick")
    call sheet%line(x0 + 167.0_wp, y0 + 15.0_wp, x0 + 167.0_wp, y0 + 35.0_wp, "thick")
    do i = 1, 2
      call sheet%line(x0 + 135.0_wp + 5.0_wp * i, y0 + 20.0_wp, x0 + 135.0_wp + 5.0_wp * i, y0 + 35.0_wp, "thin")
    end do
    call sheet%line(x0 + 155.0_wp, y0 + 35.0_wp, x0 + 155.0_wp, y0 + 40.0_wp, "thin")

    ! the headings
    call heading(sheet, x0 + 3.5_wp, y0 + 24.0_wp, words("Rev.", "Изм."))
    call heading(sheet, x0 + 12.0_wp, y0 + 24.0_wp, words("Sheet", "Лист"))
    call heading(sheet, x0 + 28.5_wp, y0 + 24.0_wp, words("Doc. No.", "№ докум."))
    call heading(sheet, x0 + 47.5_wp, y0 + 24.0_wp, words("Sign.", "Подп."))
    call heading(sheet, x0 + 60.0_wp, y0 + 24.0_wp, words("Date", "Дата"))
    call role(sheet, y0 + 29.0_wp, words("Drawn", "Разраб."))
    call role(sheet, y0 + 34.0_wp, words("Checked", "Пров."))
    call role(sheet, y0 + 39.0_wp, words("Tech. ctrl", "Т.контр."))
    call role(sheet, y0 + 49.0_wp, words("Std. ctrl", "Н.контр."))
    call role(sheet, y0 + 54.0_wp, words("Approved", "Утв."))
    call heading(sheet, x0 + 142.5_wp, y0 + 19.0_wp, words("Lit.", "Лит."))
    call heading(sheet, x0 + 158.5_wp, y0 + 19.0_wp, words("Mass", "Масса"))
    call heading(sheet, x0 + 176.0_wp, y0 + 19.0_wp, words("Scale", "Масштаб"))
    call heading(sheet, x0 + 145.0_wp, y0 + 39.0_wp, words("Sheet ", "Лист ")//int_str(block%sheet_number))
    call heading(sheet, x0 + 170.0_wp, y0 + 39.0_wp, words("Sheets ", "Листов ")//int_str(block%sheet_count))

    ! the entries
    call sheet%text(x0 + 137.5_wp, y0 + 29.0_wp, words("S", "У"), "cell", anchor_middle, size=3.0_wp, plain=.true.)
    if (len(block%scale) > 0) call sheet%text(x0 + 176.0_wp, y0 + 29.0_wp, fitted_text(block%scale, 16.0_wp, &
      3.0_wp), "cell", anchor_middle, size=3.0_wp, plain=.true.)
    if (len(block%designation) > 0) call sheet%text(x0 + 125.0_wp, y0 + 9.5_wp, fitted_text(block%designation, &
      116.0_wp, 3.5_wp), "cell", anchor_middle, size=3.5_wp, plain=.true.)
    ! the drawing's name: smaller, then on two lines, to fit its 70 x 25 mm
    name = block%drawing_name
    size = min(3.0_wp, 66.0_wp / (0.6_wp * max(1, char_count(name))))
    if (size >= 2.2_wp) then
      call sheet%text(x0 + 100.0_wp, y0 + 29.0_wp, name, "cell", anchor_middle, size=floor(size * 10.0_wp) / 10.0_wp)
    else
      call two_lines(sheet, name)
    end if
    call sheet%text(x0 + 100.0_wp, y0 + 46.5_wp, fitted_text(version_string, 66.0_wp, entry_size), "cell", &
      anchor_middle, size=entry_size, plain=.true.)
    if (len(block%student%stamp) > 0) then
      date = block%student%stamp(:max(0, index(block%student%stamp, " ") - 1))
      ! date as DD.MM.YY (the column is 10 mm)
      if (len(date) == 10) date = date(1:6)//date(9:10)
      call sheet%text(x0 + 18.0_wp, y0 + 29.0_wp, fitted_text(block%student%name, 22.0_wp, entry_size), "cell", &
        size=entry_size, plain=.true.)
      call sheet%text(x0 + 60.0_wp, y0 + 29.0_wp, date, "cell", anchor_middle, size=1.9_wp, plain=.true.)
      call sheet%text(x0 + 100.0_wp, y0 + 51.5_wp, words("run ", "расчет ")//block%student%stamp, "cell", anchor_middle, &
        size=entry_size, plain=.true.)
      call sheet%text(x0 + 160.0_wp, y0 + 46.5_wp, fitted_text(words("group ", "группа ")//block%student%group, 46.0_wp, &
        entry_size), "cell", anchor_middle, size=entry_size, plain=.true.)
      call sheet%text(x0 + 160.0_wp, y0 + 51.5_wp, fitted_text(words("variant ", "вариант ")//block%student%variant, &
        46.0_wp, entry_size), "cell", anchor_middle, size=entry_size, plain=.true.)
    end if
  contains
    !> The English or the Russian word, by the sheet's language.
    pure function words(english, russian) result(text)
      character(*), intent(in) :: english, russian
      character(len=:), allocatable :: text
      if (sheet%lang == lang_ru) then
        text = russian
      else
        text = english
      end if
    end function words
    !> A cell's heading, centred at (x, y).
    pure subroutine heading(sheet, x, y, text)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: x, y
      character(*), intent(in) :: text
      call sheet%text(x, y, text, "cell", anchor_middle, plain=.true.)
    end subroutine heading
    !> A signature row's role in the first 17 mm.
    pure subroutine role(sheet, y, text)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: y
      character(*), intent(in) :: text
      call sheet%text(x0 + 1.0_wp, y, text, "cell", plain=.true.)
    end subroutine role
    !> The drawing's name on two lines, split at the blank nearest its middle.
    pure subroutine two_lines(sheet, text)
      type(sheet_t), intent(inout) :: sheet
      character(*), intent(in) :: text
      integer :: i, cut
      real(wp) :: s
      cut = 0
      do i = 1, len(text)
        if (text(i:i) /= " ") cycle
        if (cut == 0 .or. abs(2 * i - len(text)) < abs(2 * cut - len(text))) cut = i
      end do
      if (cut == 0) cut = len(text) / 2
      s = min(3.0_wp, 66.0_wp / (0.6_wp * max(1, char_count(text(:cut)), char_count(text(cut + 1:)))))
      s = max(floor(s * 10.0_wp) / 10.0_wp, 1.6_wp)
      call sheet%text(x0 + 100.0_wp, y0 + 26.5_wp, fitted_text(trim(text(:cut)), 66.0_wp, s), "cell", anchor_middle, &
        size=s)
      call sheet%text(x0 + 100.0_wp, y0 + 26.5_wp + 1.3_wp * s, fitted_text(trim(adjustl(text(cut + 1:))), 66.0_wp, s), &
        "cell", anchor_middle, size=s)
    end subroutine two_lines
  end subroutine put_title_block_at

  !> The older entry point: the block at the lower right corner of a sheet `width` x `height`
  !> mm written as SVG elements into `out` (nothing when the run has no student's header).
  pure subroutine put_title_block(out, table, lang, width, height, drawing_name)
    type(text_buffer_t), intent(inout) :: out
    !> The results (their student's header).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Sheet size, mm.
    real(wp), intent(in) :: width, height
    !> The drawing's name (in the sheet's language).
    character(*), intent(in), optional :: drawing_name
    type(sheet_t) :: sheet
    type(paper_t) :: paper
    integer :: i, c
    if (.not. allocated(table%student)) return
    paper%name = ""
    paper%width = width
    paper%height = height
    call sheet%open(paper, lang, "", "")
    if (present(drawing_name)) then
      call put_title_block_at(sheet, title_block_from_table(table, drawing_name, ""), width - frame_margin - block_width, &
        height - frame_margin - block_height)
    else
      call put_title_block_at(sheet, title_block_from_table(table, "", ""), width - frame_margin - block_width, &
        height - frame_margin - block_height)
    end if
    ! a sheet not on the model has not the model's style sheet: every style written out
    do i = 1, sheet%count
      associate (e => sheet%items(i))
        do c = 1, size(line_classes)
          if (line_classes(c)%name /= e%class) cycle
          e%stroke = trim(line_classes(c)%stroke)
          e%width = line_classes(c)%width
          if (len(e%fill) == 0) e%fill = trim(line_classes(c)%fill)
        end do
        e%class = ""
      end associate
    end do
    call put_sheet_elements(sheet, out)
  end subroutine put_title_block

  !> `text` cut (with "...") to fit `room` mm at font size `size` mm (0.6 x size per character),
  !> counting UTF-8 characters, not bytes (a Cyrillic name is never cut inside a letter).
  pure function fitted_text(text, room, size) result(fitted)
    character(*), intent(in) :: text
    real(wp), intent(in) :: room, size
    character(len=:), allocatable :: fitted
    integer :: most, n, i, kept
    most = max(4, int(room / (0.6_wp * size)))
    ! characters, not bytes (UTF-8 continuation bytes do not count)
    n = 0
    kept = len(text)
    do i = 1, len(text)
      if (iand(ichar(text(i:i)), 192) /= 128) then
        n = n + 1
        if (n == most - 2) kept = i - 1
      end if
    end do
    ! the cut is just before a character's first byte: whole characters stay
    if (n <= most) then
      fitted = text
    else
      fitted = text(:kept)//"..."
    end if
  end function fitted_text

end module kinetostat_title_block
