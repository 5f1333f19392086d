!> The student's title block on a sheet (`--student NAME --group G --variant N`): the main
!> inscription of ГОСТ 2.104, form 1, 185 x 55 mm, in the sheet's lower right corner, in the
!> sheet's language:
!> - left, 65 mm: the grid of changes (rows of 5 mm; columns Изм. 7, Лист 10, № докум. 23,
!>   Подп. 15, Дата 10 mm) and the signatures Разраб. (the student, the date of the run),
!>   Пров., Т.контр., Н.контр., Утв.;
!> - right, 120 mm: the document's designation (group.variant and the deck), 120 x 15; the
!>   drawing's name, 70 x 25; the letter (У, a student's drawing), mass and scale cells and
!>   sheet 1 of 1 sheets, 50 x 25; the program and the run's time, 70 x 15; the organisation
!>   field with the group and variant, 50 x 15.
!> A sheet that carries it is made title_block_height mm taller so that it covers nothing.
module kinetostat_title_block
  use kinetostat_kinds, only: wp, version_string
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: svg_rect, svg_line, svg_text
  use kinetostat_labels, only: lang_ru
  implicit none
  private
  public :: put_title_block, title_block_height

  !> Size of the block (ГОСТ 2.104 form 1), mm.
  real(wp), parameter :: block_width = 185.0_wp, block_height = 55.0_wp
  !> Height a sheet grows by to carry the block (the block and the 5 mm margin below it), mm.
  real(wp), parameter :: title_block_height = block_height + 5.0_wp
  !> Font sizes, mm: the cells' headings, the entries, the name and designation.
  real(wp), parameter :: head_size = 2.0_wp, entry_size = 2.4_wp
  !> Attributes of the lines: the thick (0.5 mm) and thin (0.18 mm) lines of the grid.
  character(*), parameter :: thick = 'stroke="#000000" stroke-width="0.5"', thin = 'stroke="#000000" stroke-width="0.18"'

contains

  !> The block at the lower right corner of a sheet `width` x `height` mm (nothing when the
  !> run has no student's header).
  pure subroutine put_title_block(out, table, lang, width, height, drawing_name)
    type(text_buffer_t), intent(inout) :: out
    !> The results (their student's header).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Sheet size, mm.
    real(wp), intent(in) :: width, height
    !> The drawing's name (in the sheet's language) for the name field; default: the deck.
    character(*), intent(in), optional :: drawing_name
    real(wp) :: x0, y0, x
    integer :: blank, i
    real(wp), parameter :: left_columns(5) = [7.0_wp, 10.0_wp, 23.0_wp, 15.0_wp, 10.0_wp]
    character(len=:), allocatable :: name, date
    if (.not. allocated(table%student_stamp)) return
    x0 = width - 5.0_wp - block_width
    y0 = height - 5.0_wp - block_height
    blank = index(table%student_stamp, " ")
    date = table%student_stamp(:blank - 1)
    ! date as DD.MM.YY (the column is 10 mm)
    if (len(date) == 10) date = date(1:6)//date(9:10)
    name = table%deck
    if (present(drawing_name)) name = drawing_name

    ! the frame and the thick lines
    call out%put(svg_rect(x0, y0, block_width, block_height, 'fill="#ffffff" '//thick))
    call out%put(svg_line(x0 + 65.0_wp, y0, x0 + 65.0_wp, y0 + block_height, thick))
    call out%put(svg_line(x0 + 65.0_wp, y0 + 15.0_wp, x0 + block_width, y0 + 15.0_wp, thick))
    call out%put(svg_line(x0 + 65.0_wp, y0 + 40.0_wp, x0 + block_width, y0 + 40.0_wp, thick))
    call out%put(svg_line(x0 + 135.0_wp, y0 + 15.0_wp, x0 + 135.0_wp, y0 + block_height, thick))
    call out%put(svg_line(x0, y0 + 25.0_wp, x0 + 65.0_wp, y0 + 25.0_wp, thick))
    call out%put(svg_line(x0, y0 + 20.0_wp, x0 + 65.0_wp, y0 + 20.0_wp, thick))
    ! the left part: rows of 5 mm; the columns over the changes' rows, two over the signatures
    do i = 1, 10
      if (i == 4 .or. i == 5) cycle
      call out%put(svg_line(x0, y0 + 5.0_wp * i, x0 + 65.0_wp, y0 + 5.0_wp * i, thin))
    end do
    x = x0
    do i = 1, 4
      x = x + left_columns(i)
      if (i == 1) then
        call out%put(svg_line(x, y0, x, y0 + 25.0_wp, thick))
      else
        call out%put(svg_line(x, y0, x, y0 + block_height, thick))
      end if
    end do
    ! the right part: letter, mass, scale; sheet, sheets
    call out%put(svg_line(x0 + 135.0_wp, y0 + 20.0_wp, x0 + block_width, y0 + 20.0_wp, thin))
    call out%put(svg_line(x0 + 135.0_wp, y0 + 35.0_wp, x0 + block_width, y0 + 35.0_wp, thin))
    call out%put(svg_line(x0 + 150.0_wp, y0 + 15.0_wp, x0 + 150.0_wp, y0 + 35.0_wp, thick))
    call out%put(svg_line(x0 + 167.0_wp, y0 + 15.0_wp, x0 + 167.0_wp, y0 + 35.0_wp, thick))
    do i = 1, 2
      call out%put(svg_line(x0 + 135.0_wp + 5.0_wp * i, y0 + 20.0_wp, x0 + 135.0_wp + 5.0_wp * i, y0 + 35.0_wp, thin))
    end do
    call out%put(svg_line(x0 + 155.0_wp, y0 + 35.0_wp, x0 + 155.0_wp, y0 + 40.0_wp, thin))

    ! the headings
    call out%put(heading(x0 + 3.5_wp, y0 + 24.0_wp, words("Rev.", "Изм.")))
    call out%put(heading(x0 + 12.0_wp, y0 + 24.0_wp, words("Sheet", "Лист")))
    call out%put(heading(x0 + 28.5_wp, y0 + 24.0_wp, words("Doc. No.", "№ докум.")))
    call out%put(heading(x0 + 47.5_wp, y0 + 24.0_wp, words("Sign.", "Подп.")))
    call out%put(heading(x0 + 60.0_wp, y0 + 24.0_wp, words("Date", "Дата")))
    call out%put(role(y0 + 29.0_wp, words("Drawn", "Разраб.")))
    call out%put(role(y0 + 34.0_wp, words("Checked", "Пров.")))
    call out%put(role(y0 + 39.0_wp, words("Tech. ctrl", "Т.контр.")))
    call out%put(role(y0 + 49.0_wp, words("Std. ctrl", "Н.контр.")))
    call out%put(role(y0 + 54.0_wp, words("Approved", "Утв.")))
    call out%put(heading(x0 + 142.5_wp, y0 + 19.0_wp, words("Lit.", "Лит.")))
    call out%put(heading(x0 + 158.5_wp, y0 + 19.0_wp, words("Mass", "Масса")))
    call out%put(heading(x0 + 176.0_wp, y0 + 19.0_wp, words("Scale", "Масштаб")))
    call out%put(heading(x0 + 145.0_wp, y0 + 39.0_wp, words("Sheet 1", "Лист 1")))
    call out%put(heading(x0 + 170.0_wp, y0 + 39.0_wp, words("Sheets 1", "Листов 1")))

    ! the entries
    call out%put(svg_text(x0 + 18.0_wp, y0 + 29.0_wp, fitted_text(table%student_name, 22.0_wp, entry_size), &
      'font-size="2.4"'))
    call out%put(svg_text(x0 + 60.0_wp, y0 + 29.0_wp, date, 'font-size="1.9" text-anchor="middle"'))
    call out%put(svg_text(x0 + 137.5_wp, y0 + 29.0_wp, words("S", "У"), 'font-size="3.0" text-anchor="middle"'))
    call out%put(svg_text(x0 + 125.0_wp, y0 + 9.5_wp, fitted_text(table%student_group//"."//table%student_variant// &
      "   "//table%deck, 116.0_wp, 3.5_wp), 'font-size="3.5" text-anchor="middle"'))
    call out%put(svg_text(x0 + 100.0_wp, y0 + 29.0_wp, fitted_text(name, 66.0_wp, 3.0_wp), &
      'font-size="3.0" text-anchor="middle"'))
    call out%put(svg_text(x0 + 100.0_wp, y0 + 46.5_wp, fitted_text(version_string, 66.0_wp, entry_size), &
      'font-size="2.4" text-anchor="middle"'))
    call out%put(svg_text(x0 + 100.0_wp, y0 + 51.5_wp, words("run ", "расчет ")//table%student_stamp, &
      'font-size="2.4" text-anchor="middle"'))
    call out%put(svg_text(x0 + 160.0_wp, y0 + 46.5_wp, fitted_text(words("group ", "группа ")//table%student_group, 46.0_wp, &
      entry_size), 'font-size="2.4" text-anchor="middle"'))
    call out%put(svg_text(x0 + 160.0_wp, y0 + 51.5_wp, fitted_text(words("variant ", "вариант ")//table%student_variant, &
      46.0_wp, entry_size), 'font-size="2.4" text-anchor="middle"'))
  contains
    !> The English or the Russian word, by the sheet's language.
    pure function words(english, russian) result(text)
      character(*), intent(in) :: english, russian
      character(len=:), allocatable :: text
      if (lang == lang_ru) then
        text = russian
      else
        text = english
      end if
    end function words
    !> A cell's heading, centred at (x, y).
    pure function heading(x, y, text) result(line)
      real(wp), intent(in) :: x, y
      character(*), intent(in) :: text
      character(len=:), allocatable :: line
      line = svg_text(x, y, text, 'font-size="2.0" text-anchor="middle"')
    end function heading
    !> A signature row's role in the first 17 mm.
    pure function role(y, text) result(line)
      real(wp), intent(in) :: y
      character(*), intent(in) :: text
      character(len=:), allocatable :: line
      line = svg_text(x0 + 1.0_wp, y, text, 'font-size="2.0"')
    end function role
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
