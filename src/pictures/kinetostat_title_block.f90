!> The student's title block on a sheet (`--student NAME --group G --variant N`): a small
!> framed block in the sheet's lower right corner after the main inscription of ГОСТ 2.104
!> (who drew it, group, variant; date and time of the run; the program), in the sheet's
!> language.
module kinetostat_title_block
  use kinetostat_kinds, only: wp, version_string
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: svg_rect, svg_line, svg_text
  use kinetostat_labels, only: lang_ru
  implicit none
  private
  public :: put_title_block, title_block_height

  !> Size of the block, mm.
  real(wp), parameter :: block_width = 130.0_wp, title_block_height = 16.0_wp

contains

  !> The block at the lower right corner of a sheet `width` x `height` mm (nothing when the
  !> run has no student's header).
  pure subroutine put_title_block(out, table, lang, width, height)
    type(text_buffer_t), intent(inout) :: out
    !> The results (their student's header).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Sheet size, mm.
    real(wp), intent(in) :: width, height
    real(wp) :: x0, y0
    integer :: blank
    if (.not. allocated(table%student_stamp)) return
    x0 = width - 10.0_wp - block_width
    y0 = height - 4.0_wp - title_block_height
    blank = index(table%student_stamp, " ")
    call out%put(svg_rect(x0, y0, block_width, title_block_height, 'fill="none" stroke="#000000" stroke-width="0.5"'))
    call out%put(svg_line(x0, y0 + 8.0_wp, x0 + block_width, y0 + 8.0_wp, 'class="frame"'))
    if (lang == lang_ru) then
      call out%put(svg_text(x0 + 2.0_wp, y0 + 5.5_wp, "Студент: "//table%student_name//" · Группа: "// &
        table%student_group//" · Вариант: "//table%student_variant, 'class="label"'))
      call out%put(svg_text(x0 + 2.0_wp, y0 + 13.5_wp, "Дата: "//table%student_stamp(:blank - 1)//" · Время: "// &
        table%student_stamp(blank + 1:)//" · "//version_string, 'class="small"'))
    else
      call out%put(svg_text(x0 + 2.0_wp, y0 + 5.5_wp, "Student: "//table%student_name//" · Group: "// &
        table%student_group//" · Variant: "//table%student_variant, 'class="label"'))
      call out%put(svg_text(x0 + 2.0_wp, y0 + 13.5_wp, "Date: "//table%student_stamp(:blank - 1)//" · Time: "// &
        table%student_stamp(blank + 1:)//" · "//version_string, 'class="small"'))
    end if
  end subroutine put_title_block

end module kinetostat_title_block
