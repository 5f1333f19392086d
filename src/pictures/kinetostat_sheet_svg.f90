!> The SVG writer of the drawing model (kinetostat_sheet): one self-contained document of the
!> sheet's paper size (width and height in mm, user units mm), its title and description,
!> the style sheet made from the model's classes, a white background, then every entity in
!> order: <line>, <path> (polylines; arcs as polylines through points 5 deg apart),
!> <polygon>, <rect>, <circle>, <text> with <tspan>s for lowered and raised runs (dy of 0.3
!> and -0.4 of the font size, font size 0.7 of it), <g> for groups. Coordinates in mm with
!> two decimals (kinetostat_svg's coord); no transform on anything drawn except a rotated
!> text's own rotate(). Overrides of a class's style go into a style attribute (CSS beats
!> presentation attributes), without a class into presentation attributes. Every text and
!> attribute value goes through `escaped`, the program's XML escaper (kinetostat_escape's
!> xml_escape: also control characters and bytes that are not UTF-8 as the visible \xNN).
module kinetostat_sheet_svg
  use kinetostat_kinds, only: wp
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: coord, svg_polyline_d
  use kinetostat_escape, only: escaped => xml_escape
  use kinetostat_scales, only: scale_number
  use kinetostat_typeset, only: text_run_t, run_base, run_sub, run_sup, sub_size, sub_shift, sup_shift
  use kinetostat_sheet, only: sheet_t, entity_t, entity_line, entity_polyline, entity_polygon, entity_rect, &
    entity_circle, entity_arc, entity_text, entity_group, entity_group_end, anchor_middle, anchor_end, line_classes, &
    text_classes, class_font_size, arc_points
  implicit none
  private
  public :: write_sheet_svg, put_sheet_elements

contains

  !> The whole SVG document of `sheet`.
  pure subroutine write_sheet_svg(sheet, out)
    !> The sheet.
    type(sheet_t), intent(in) :: sheet
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    integer :: i
    character(len=:), allocatable :: rule
    associate (w => sheet%paper%width, h => sheet%paper%height)
      call out%put('<?xml version="1.0" encoding="UTF-8"?>')
      call out%put('<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="'//coord(w)//'mm" height="'// &
        coord(h)//'mm" viewBox="0 0 '//coord(w)//" "//coord(h)//'">')
      call out%put("<title>"//escaped(sheet%title)//"</title>")
      call out%put("<desc>"//escaped(sheet%description)//"</desc>")
      call out%put("<style>")
      call out%put("text { font-family: sans-serif; fill: #000000; }")
      do i = 1, size(text_classes)
        associate (c => text_classes(i))
          rule = "."//trim(c%name)//" { font-size: "//scale_number(c%size)//"px;"
          if (c%bold) rule = rule//" font-weight: bold;"
          if (c%italic) rule = rule//" font-style: italic;"
          if (c%fill /= "#000000") rule = rule//" fill: "//c%fill//";"
          call out%put(rule//" }")
        end associate
      end do
      do i = 1, size(line_classes)
        associate (c => line_classes(i))
          rule = "."//trim(c%name)//" { fill: "//trim(c%fill)//"; stroke: "//trim(c%stroke)//";"
          if (c%width > 0.0_wp) rule = rule//" stroke-width: "//scale_number(c%width)//";"
          if (len_trim(c%dash) > 0) rule = rule//" stroke-dasharray: "//trim(c%dash)//";"
          if (c%round) rule = rule//" stroke-linejoin: round;"
          call out%put(rule//" }")
        end associate
      end do
      call out%put("</style>")
      call out%put('<rect x="0" y="0" width="'//coord(w)//'" height="'//coord(h)//'" class="paper"/>')
    end associate
    call put_sheet_elements(sheet, out)
    call out%put("</svg>")
  end subroutine write_sheet_svg

  !> The sheet's entities as SVG elements, one a line (no document around them).
  pure subroutine put_sheet_elements(sheet, out)
    !> The sheet.
    type(sheet_t), intent(in) :: sheet
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    integer :: i, k
    real(wp), allocatable :: px(:), py(:)
    character(len=:), allocatable :: points
    do i = 1, sheet%count
      associate (e => sheet%items(i))
        select case (e%kind)
        case (entity_line)
          call out%put('<line x1="'//coord(e%x(1))//'" y1="'//coord(e%y(1))//'" x2="'//coord(e%x(2))//'" y2="'// &
            coord(e%y(2))//'"'//styling(e, .false.)//"/>")
        case (entity_polyline)
          call out%put('<path d="'//svg_polyline_d(e%x, e%y)//'"'//styling(e, .true.)//"/>")
        case (entity_arc)
          call arc_points(e, px, py)
          call out%put('<path d="'//svg_polyline_d(px, py)//'"'//styling(e, .true.)//"/>")
        case (entity_polygon)
          points = ""
          do k = 1, size(e%x)
            if (k > 1) points = points//" "
            points = points//coord(e%x(k))//","//coord(e%y(k))
          end do
          call out%put('<polygon points="'//points//'"'//styling(e, .false.)//"/>")
        case (entity_rect)
          call out%put('<rect x="'//coord(e%x(1))//'" y="'//coord(e%y(1))//'" width="'//coord(e%x(2) - e%x(1))// &
            '" height="'//coord(e%y(2) - e%y(1))//'"'//styling(e, .false.)//"/>")
        case (entity_circle)
          call out%put('<circle cx="'//coord(e%x(1))//'" cy="'//coord(e%y(1))//'" r="'//coord(e%radius)//'"'// &
            styling(e, .false.)//"/>")
        case (entity_text)
          call out%put(text_element(e))
        case (entity_group)
          call out%put("<g"//styling(e, .false.)//">")
        case (entity_group_end)
          call out%put("</g>")
        case default
          continue
        end select
      end associate
    end do
  end subroutine put_sheet_elements

  !> The attributes of an entity's style and data: its class, its overrides (in a style
  !> attribute when it has a class, else as presentation attributes), fill="none" for an
  !> open path without a class, then its data attributes.
  pure function styling(e, open_path) result(text)
    type(entity_t), intent(in) :: e
    logical, intent(in) :: open_path
    character(len=:), allocatable :: text, css, fill
    logical :: has_class
    integer :: k
    has_class = .false.
    if (allocated(e%class)) has_class = len(e%class) > 0
    text = ""
    if (has_class) text = ' class="'//e%class//'"'
    fill = ""
    if (allocated(e%fill)) fill = e%fill
    if (open_path .and. .not. has_class .and. len(fill) == 0) fill = "none"
    if (has_class) then
      css = ""
      if (allocated(e%stroke)) call add_css(css, "stroke", e%stroke)
      if (e%width >= 0.0_wp) call add_css(css, "stroke-width", scale_number(e%width))
      call add_css(css, "fill", fill)
      if (allocated(e%dash)) call add_css(css, "stroke-dasharray", e%dash)
      if (len(css) > 0) text = text//' style="'//css//'"'
    else
      if (allocated(e%stroke)) then
        if (len(e%stroke) > 0) text = text//' stroke="'//e%stroke//'"'
      end if
      if (e%width >= 0.0_wp) text = text//' stroke-width="'//scale_number(e%width)//'"'
      if (len(fill) > 0) text = text//' fill="'//fill//'"'
      if (allocated(e%dash)) then
        if (len(e%dash) > 0) text = text//' stroke-dasharray="'//e%dash//'"'
      end if
    end if
    if (allocated(e%data_names)) then
      do k = 1, size(e%data_names)
        text = text//" "//trim(e%data_names(k))//'="'//escaped(trim(e%data_values(k)))//'"'
      end do
    end if
  contains
    pure subroutine add_css(css, name, value)
      character(len=:), allocatable, intent(inout) :: css
      character(*), intent(in) :: name, value
      if (len(value) == 0) return
      if (len(css) > 0) css = css//"; "
      css = css//name//": "//value
    end subroutine add_css
  end function styling

  !> A <text> element with its runs (lowered and raised ones as <tspan>s).
  pure function text_element(e) result(line)
    type(entity_t), intent(in) :: e
    character(len=:), allocatable :: line, css
    real(wp) :: offset, target, run_size
    integer :: k
    line = '<text x="'//coord(e%x(1))//'" y="'//coord(e%y(1))//'"'
    if (len(e%class) > 0) line = line//' class="'//e%class//'"'
    select case (e%anchor)
    case (anchor_middle)
      line = line//' text-anchor="middle"'
    case (anchor_end)
      line = line//' text-anchor="end"'
    case default
      continue
    end select
    ! what differs from the class: in a style attribute (CSS rules beat presentation attributes)
    css = ""
    if (abs(e%size - class_font_size(e%class)) > 1.0e-9_wp .or. len(e%class) == 0) css = css//"; font-size: "// &
      scale_number(e%size)//"px"
    if (e%bold) css = css//"; font-weight: bold"
    if (e%italic) css = css//"; font-style: italic"
    if (allocated(e%fill)) then
      if (len(e%fill) > 0) css = css//"; fill: "//e%fill
    end if
    if (len(css) > 0) line = line//' style="'//css(3:)//'"'
    if (e%rotation /= 0.0_wp) line = line//' transform="rotate('//scale_number(e%rotation)//" "//coord(e%x(1))//" "// &
      coord(e%y(1))//')"'
    ! the blanks next to a <tspan> are kept (by default a renderer may drop them)
    if (size(e%runs) > 1) line = line//' xml:space="preserve"'
    line = line//">"
    offset = 0.0_wp
    do k = 1, size(e%runs)
      select case (e%runs(k)%shift)
      case (run_sub)
        target = anint(sub_shift * e%size * 100.0_wp) / 100.0_wp
        run_size = sub_size * e%size
      case (run_sup)
        target = -anint(sup_shift * e%size * 100.0_wp) / 100.0_wp
        run_size = sub_size * e%size
      case default
        target = 0.0_wp
        run_size = e%size
      end select
      if (target == offset .and. e%runs(k)%shift == run_base) then
        line = line//escaped(e%runs(k)%text)
      else
        line = line//'<tspan dy="'//coord(target - offset)//'"'
        if (e%runs(k)%shift /= run_base) line = line//' font-size="'//coord(run_size)//'"'
        line = line//">"//escaped(e%runs(k)%text)//"</tspan>"
      end if
      offset = target
    end do
    line = line//"</text>"
  end function text_element

end module kinetostat_sheet_svg
