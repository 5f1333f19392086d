!> The course's sheet of the machine dynamics (kinetostat sheets: dynamics.svg) on the drawing
!> model, from a run with a steady cycle (the dynamics columns and figures of the step table):
!> over the cycle, each chart at a round scale μ of its quantity and the one μφ of the angle,
!> - the reduced moments M_red (M_пр) with the driving moment M_d (M_д);
!> - the work diagrams: the driving moment's work A_Md and the loads' A_red (A_д for the one
!>   that comes out positive over the cycle, A_с for the other: an engine's M_d is negative),
!>   and dT = A_Md + A_red;
!> - the reduced moment of inertia J_red (J_пр);
!> - Merzalov's T_I with its extremes and their difference;
!> - the true speed omega1 with its mean, largest and smallest, and eps1;
!> - Wittenbauer's diagram dT against J_red with the origin O, the tangents at the angles
!>   ψ_max, ψ_min (slopes omega_max^2/2 and omega_min^2/2) and the segment kl they cut off the
!>   dT axis: J_flywheel = kl / (delta omega_m^2);
!> - the flywheel as a disc (its section at a ГОСТ 2.302 scale, D and b dimensioned) and the
!>   table of the figures (M_d, J_flywheel, Merzalov's estimate, delta, the speeds, D, b, m).
module kinetostat_dynamics_sheet
  use kinetostat_kinds, only: wp, pi, version_string
  use kinetostat_format, only: short_number, fixed_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_run_tally, only: flywheel_disc
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_sheet, only: sheet_t, paper_t, course_paper, layer_text, layer_charts, layer_profile, &
    anchor_start, anchor_middle, anchor_end, class_font_size
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, block_height, header_indent, &
    course_title, course_data_line, block_width
  use kinetostat_mechanism_sheet, only: fitted_size
  use kinetostat_scales, only: round_scale, nice_step, scale_number, standard_drawing_scale, drawing_scale_t
  use kinetostat_run_sheet, only: put_axes
  use kinetostat_design_sheet, only: words, put_dimension, put_table, dot, text_width
  implicit none
  private
  public :: draw_dynamics_sheet, sheet_header, plot_t, put_cycle_chart, put_cycle_curve, plot_box

  !> Gap between panels, mm.
  real(wp), parameter :: gap = 6.0_wp
  !> A4 portrait: the height of the row of Wittenbauer's diagram and the flywheel, mm.
  real(wp), parameter :: portrait_row = 66.0_wp
  !> Colours of the curves.
  character(*), parameter :: blue = "#1f77b4", red = "#d62728", green = "#2ca02c", black = "#000000", &
    grey = "#555555"

  !> A chart's plot: its rectangle on the sheet and the ranges drawn.
  type :: plot_t
    real(wp) :: left = 0.0_wp, top = 0.0_wp, width = 1.0_wp, height = 1.0_wp
    real(wp) :: xlo = 0.0_wp, xhi = 1.0_wp, ylo = 0.0_wp, yhi = 1.0_wp
    !> The heading's second line (its scales, where one line would be smaller than 2.5 mm):
    !> how much lower the plot and the panel's foot are, mm (0: one line, or two that fit).
    real(wp) :: head = 0.0_wp
  contains
    procedure :: sx => plot_x
    procedure :: sy => plot_y
  end type plot_t

contains

  !> The dynamics sheet of a run with a steady cycle on `paper`'s size (course_paper: A1 ..
  !> A3 landscape, three columns; A4 portrait, two).
  !> Not pure: its inner procedures draw into the host's sheet.
  subroutine draw_dynamics_sheet(title, table, paper, lang, sheet)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The run (every row of the cycle; its dynamics columns and figures).
    type(step_table_t), intent(in) :: table
    type(paper_t), intent(in) :: paper
    integer, intent(in) :: lang
    type(sheet_t), intent(out) :: sheet
    real(wp), allocatable :: phi(:), md(:)
    real(wp) :: inner(4), cw, x1, x2, x3, top, hmax, mu_phi, y, wm, wmax, wmin, jfw, delta, md_mean
    logical :: portrait
    type(paper_t) :: page
    real(wp) :: bottom3
    !> The flywheel as a disc: its diameter and width, m, and mass, kg (0 without one).
    real(wp) :: disc_d, disc_b, disc_m
    type(plot_t) :: p
    type(drawing_scale_t) :: disc_scale
    !> The length of a curve's stroke in a legend, mm.
    real(wp), parameter :: legend_stroke = 5.0_wp
    character(len=:), allocatable :: deg, nm, joule, kgm2, xlabel, a_drive, a_load
    integer :: kmax, kmin
    !> The names of the curves of the chart drawn last, placed when all its lines are drawn
    !> (names): the text, its colour and dash, the point of the curve it names.
    character(len=32) :: name_text(4), name_colour(4), name_dash(4)
    real(wp) :: name_x(4), name_y(4)
    integer :: names_queued

    names_queued = 0
    page = course_paper(paper%name)
    call sheet%open(page, lang, words("Machine dynamics", "Динамический анализ машины", lang), &
      "kinetostat sheets: the dynamics sheet: reduced moments, work diagrams, dT, T_I, "// &
      "J_red, omega1, eps1, Wittenbauer's diagram with the tangents and kl, the flywheel.")
    deg = unit_word("deg", lang)
    nm = unit_word("N*m", lang)
    joule = unit_word("J", lang)
    kgm2 = unit_word("kg*m^2", lang)
    phi = table%rows(table%input_column, :)
    xlabel = "φ1, "//deg
    wm = table%dynamics%omega_mean
    wmax = table%dynamics%omega_max
    wmin = table%dynamics%omega_min
    jfw = table%dynamics%j_flywheel
    delta = table%dynamics%delta
    md_mean = table%dynamics%m_d
    call flywheel_disc(table%dynamics, disc_d, disc_b, disc_m)
    md = column(table%driver)
    ! the disc's scale first: the title block's Масштаб is the flywheel's (the sheet's one drawing)
    ! (A4 portrait: two columns of charts, Wittenbauer's diagram and the flywheel under them)
    portrait = .not. page%landscape
    inner = page%inside()
    cw = (inner(3) - inner(1) - 4.0_wp * gap) / 3.0_wp
    if (portrait) cw = (inner(3) - inner(1) - 3.0_wp * gap) / 2.0_wp
    disc_scale = standard_drawing_scale(min(0.5_wp * cw - 30.0_wp, 120.0_wp) / &
      max(disc_d, 1.0e-9_wp) / 1000.0_wp)
    if (jfw > 0.0_wp) then
      call put_sheet_format(sheet, title_block_from_table(table, words("Machine dynamics and the flywheel", &
        "Динамический анализ машины. Маховик", lang), disc_scale%text))
    else
      call put_sheet_format(sheet, title_block_from_table(table, words("Machine dynamics", &
        "Динамический анализ машины", lang), ""))
    end if
    call sheet_header(sheet, title, table, lang, words("Machine dynamics: steady cycle, the flywheel", &
      "Динамический анализ машины: установившееся движение, маховик", lang))

    x1 = inner(1) + gap
    x2 = x1 + cw + gap
    x3 = x2 + cw + gap
    top = inner(2) + 24.0_wp
    hmax = (inner(4) - top - 2.0_wp * gap) / 3.0_wp
    ! (A4 portrait: three rows of charts over Wittenbauer's diagram and the flywheel)
    if (portrait) hmax = (inner(4) - block_height - gap - top - portrait_row) / 3.0_wp - gap
    ! one μφ for every chart over the cycle
    mu_phi = round_scale(maxval(phi) - minval(phi), cw - 24.0_wp)

    ! the driving (A_д) and the resisting (A_с) work: by the sign of M_d
    if (md_mean >= 0.0_wp) then
      a_drive = "A_Md"
      a_load = "A_red"
    else
      a_drive = "A_red"
      a_load = "A_Md"
    end if

    ! column 1: M_red with M_d; the work diagrams and dT; J_red
    y = top
    call chart(x1, y, [column("M_red"), md], nm, "M", words("Reduced moments M_red and M_d", &
      "Приведенные моменты M_пр и M_д", lang), p)
    call curve(p, column("M_red"), blue, "", words("M_red", "M_пр", lang))
    call curve(p, md, black, "2 1", words("M_d", "M_д", lang))
    call names(p)
    y = y + chart_height(p) + gap
    call chart(x1, y, [column("A_Md"), column("A_red"), column("dT")], joule, "A", words( &
      "Work of the forces A_d, A_r and dT = A_d + A_r", "Работы сил A_д, A_с и ΔT = A_д + A_с", lang), p)
    call curve(p, column(a_drive), green, "", words("A_d", "A_д", lang))
    call curve(p, column(a_load), red, "", words("A_r", "A_с", lang))
    call curve(p, column("dT"), black, "", "ΔT")
    call names(p)
    y = y + chart_height(p) + gap
    call chart(x1, y, [column("J_red")], kgm2, "J", words("Reduced moment of inertia J_red", &
      "Приведенный момент инерции J_пр", lang), p, zero=.true.)
    call curve(p, column("J_red"), blue, "", words("J_red", "J_пр", lang))
    call names(p)

    ! column 2: T_I with its extremes; omega1; eps1 (down to the title block when the column
    ! reaches over it: A3)
    if (.not. portrait .and. x2 + cw > inner(3) - block_width) then
      hmax = (inner(4) - block_height - gap - top - 2.0_wp * gap) / 3.0_wp
    end if
    y = top
    call chart(x2, y, [column("T_I")], joule, "T", words("Merzalov's T_I (first group's energy)", &
      "Кинетическая энергия T_I (метод Мерцалова)", lang), p)
    call curve(p, column("T_I"), blue, "", "T_I")
    kmax = maxloc(column("T_I"), dim=1)
    kmin = minloc(column("T_I"), dim=1)
    call sheet%line(p%left, p%sy(column_at("T_I", kmax)), p%left + p%width, p%sy(column_at("T_I", kmax)), "mean")
    call sheet%line(p%left, p%sy(column_at("T_I", kmin)), p%left + p%width, p%sy(column_at("T_I", kmin)), "mean")
    call dot(sheet, [p%sx(phi(kmax)), p%sy(column_at("T_I", kmax))], red, 0.8_wp)
    call dot(sheet, [p%sx(phi(kmin)), p%sy(column_at("T_I", kmin))], red, 0.8_wp)
    call names(p)
    ! (A4 portrait: the extremes under the chart, its plot too low for labels clear of its lines)
    ! (and ΔT; J_I = ΔT/(δ ω_m²) is the flywheel table's J by Merzalov)
    if (portrait) then
      call foot(p, "T_I "//words("max", "наиб", lang)//" = "//short_number(column_at("T_I", kmax))//" "//joule// &
        ",  T_I "//words("min", "наим", lang)//" = "//short_number(column_at("T_I", kmin))//" "//joule// &
        ",  ΔT = "//short_number(column_at("T_I", kmax) - column_at("T_I", kmin))//" "//joule)
    else
      call sheet%place_label("T_I "//words("max", "наиб", lang)//" = "//short_number(column_at("T_I", kmax))// &
        " "//joule, "small", &
        p%sx(phi(kmax)), p%sy(column_at("T_I", kmax)), -0.5_wp * pi, plot_box(p))
      call sheet%place_label("T_I "//words("min", "наим", lang)//" = "//short_number(column_at("T_I", kmin))// &
        " "//joule, "small", &
        p%sx(phi(kmin)), p%sy(column_at("T_I", kmin)), 0.5_wp * pi, plot_box(p))
    end if
    if (.not. portrait) call foot(p, "ΔT = T_I "//words("max", "наиб", lang)//" − T_I "//words("min", "наим", lang)// &
      " = "//short_number(column_at("T_I", kmax) - column_at("T_I", kmin))// &
      " "//joule//";  J_I = ΔT/(δ · omega_m^2) = "// &
      short_number((column_at("T_I", kmax) - column_at("T_I", kmin)) / &
      (max(delta, 1.0e-300_wp) * wm**2))//" "//kgm2)
    y = y + chart_height(p) + gap
    call chart(x2, y, [column("omega1"), wmax, wmin], unit_word("rad/s", lang), "ω", &
      words("True speed of the input link ω1", &
      "Истинная угловая скорость начального звена ω1", lang), p, zero=.false.)
    call sheet%line(p%left, p%sy(wm), p%left + p%width, p%sy(wm), "mean")
    call sheet%line(p%left, p%sy(wmax), p%left + p%width, p%sy(wmax), "mean")
    call sheet%line(p%left, p%sy(wmin), p%left + p%width, p%sy(wmin), "mean")
    call curve(p, column("omega1"), blue, "", "ω1")
    call names(p)
    if (portrait) then
      call foot(p, "ω_m = "//short_number(wm)//",  ω_max = "//short_number(wmax)//",  ω_min = "// &
        short_number(wmin)//" "//unit_word("rad/s", lang))
    else
      call level(p, wm, "ω_m = "//short_number(wm))
      call level(p, wmax, "ω_max = "//short_number(wmax))
      call level(p, wmin, "ω_min = "//short_number(wmin))
    end if
    y = y + chart_height(p) + gap
    call chart(x2, y, [column("eps1")], unit_word("rad/s^2", lang), "ε", &
      words("Angular acceleration ε1", "Угловое ускорение начального звена ε1", lang), p)
    call curve(p, column("eps1"), blue, "", "ε1")
    call names(p)

    ! column 3: Wittenbauer's diagram; the flywheel and the figures above the title block
    bottom3 = inner(4) - block_height - gap
    if (portrait) then
      y = bottom3 - portrait_row
      call wittenbauer(x1, y, cw, bottom3 - y)
      call flywheel(x2, y, cw, bottom3 - y)
    else
      call wittenbauer(x3, top, cw, 0.55_wp * (bottom3 - top))
      call flywheel(x3, top + 0.55_wp * (bottom3 - top) + gap, cw, bottom3 - (top + 0.55_wp * (bottom3 - top) + gap))
    end if
  contains

    !> Column `name` over the rows.
    pure function column(name) result(v)
      character(*), intent(in) :: name
      real(wp), allocatable :: v(:)
      integer :: c
      c = table%column_index(name)
      allocate (v(size(table%rows, 2)))
      v = 0.0_wp
      if (c > 0) v = table%rows(c, :)
    end function column

    !> Column `name` at row k.
    pure real(wp) function column_at(name, k)
      character(*), intent(in) :: name
      integer, intent(in) :: k
      integer :: c
      c = table%column_index(name)
      column_at = 0.0_wp
      if (c > 0) column_at = table%rows(c, k)
    end function column_at


    !> A chart over the cycle at (x0, y0) in the column's width (put_cycle_chart).
    subroutine chart(x0, y0, values, unit, sym, heading, q, zero)
      real(wp), intent(in) :: x0, y0, values(:)
      character(*), intent(in) :: unit, sym, heading
      type(plot_t), intent(out) :: q
      logical, intent(in), optional :: zero
      call put_cycle_chart(sheet, x0, y0, cw, hmax, phi, mu_phi, values, unit, sym, heading, xlabel, lang, q, zero)
    end subroutine chart

    !> A curve over the cycle; its name is queued for `names` (the chart's first curve empties
    !> the queue).
    subroutine curve(q, v, colour, dash, name)
      type(plot_t), intent(in) :: q
      real(wp), intent(in) :: v(:)
      character(*), intent(in) :: colour, dash, name
      integer :: k
      if (names_queued >= size(name_text)) names_queued = 0
      call sheet%polyline(q%sx(phi(:size(v))), q%sy(v), stroke=colour, width=0.45_wp, dash=dash)
      k = max(1, nint(0.62_wp * size(v)))
      names_queued = names_queued + 1
      name_text(names_queued) = name
      name_colour(names_queued) = colour
      name_dash(names_queued) = dash
      name_x(names_queued) = q%sx(phi(k))
      name_y(names_queued) = q%sy(v(k))
    end subroutine curve

    !> The names of the chart's curves, when every line of the chart is drawn: on A4 portrait
    !> (plots too low for a name clear of the curves and levels) a legend right of the plot,
    !> a stroke of each curve and its name, where the panel has room for it; else each name
    !> placed beside its curve.
    subroutine names(q)
      type(plot_t), intent(in) :: q
      real(wp) :: room, longest, lx, ly
      integer :: i
      room = x_panel_right(q) - (q%left + q%width)
      longest = 0.0_wp
      do i = 1, names_queued
        longest = max(longest, text_width(sheet, trim(name_text(i)), class_font_size("label")))
      end do
      call sheet%set_layer(layer_charts)
      if (portrait .and. room >= legend_stroke + 5.0_wp + longest) then
        lx = q%left + q%width + 2.5_wp
        do i = 1, names_queued
          ly = q%top + 2.0_wp + 4.0_wp * (i - 1)
          call sheet%line(lx, ly, lx + legend_stroke, ly, stroke=trim(name_colour(i)), width=0.45_wp, &
            dash=trim(name_dash(i)))
          call sheet%text(lx + legend_stroke + 1.0_wp, ly + 1.0_wp, trim(name_text(i)), "label", anchor_start, &
            colour=trim(name_colour(i)))
        end do
      else
        do i = 1, names_queued
          call sheet%place_label(trim(name_text(i)), "label", name_x(i), name_y(i), -0.5_wp * pi, plot_box(q), &
            colour=trim(name_colour(i)))
        end do
      end if
      names_queued = 0
    end subroutine names

    !> The right edge of the panel of the chart q (a chart's panel is the column's width).
    pure real(wp) function x_panel_right(q)
      type(plot_t), intent(in) :: q
      x_panel_right = q%left - 19.0_wp + cw
    end function x_panel_right

    !> The panel's height of a chart.
    pure real(wp) function chart_height(q)
      type(plot_t), intent(in) :: q
      chart_height = q%height + 26.0_wp + q%head
    end function chart_height



    !> The name of a level drawn across the plot, near its left end.
    subroutine level(q, v, name)
      type(plot_t), intent(in) :: q
      real(wp), intent(in) :: v
      character(*), intent(in) :: name
      call sheet%place_label(name, "small", q%left + 0.12_wp * q%width, q%sy(v), -0.5_wp * pi, plot_box(q))
    end subroutine level

    !> A line of text under the plot's axis label.
    subroutine foot(q, text)
      type(plot_t), intent(in) :: q
      character(*), intent(in) :: text
      call sheet%text(q%left, q%top + q%height + 12.5_wp, text, "small", anchor_start, &
        size=fitted_size(text, 2.4_wp, cw - 22.0_wp, 0.62_wp))
    end subroutine foot

    !> Wittenbauer's diagram in the panel (x0, y0, w, h): dT against J_red with the origin, the
    !> tangents of slopes omega_max^2/2 and omega_min^2/2 and the segment kl on the dT axis.
    subroutine wittenbauer(x0, y0, w, h)
      real(wp), intent(in) :: x0, y0, w, h
      real(wp), allocatable :: jr(:), dt(:)
      real(wp) :: e0, sk, sl, yk, yl, jhi, jstep, lo, hi, step, mu_j, mu_t, vmin, vmax, j_end, psi_k, psi_l
      real(wp) :: ox, oy, kl, box(4)
      type(plot_t) :: q
      integer :: kk, kl_row
      logical :: on_axis
      character(len=:), allocatable :: heading, text
      allocate (jr(size(table%rows, 2)), dt(size(table%rows, 2)))
      jr = column("J_red")
      dt = column("dT")
      ! the speed law's energy at the first row: 1/2 (J_fw + J_red) omega^2 = E0 + dT
      e0 = 0.5_wp * (jfw + jr(1)) * column_at("omega1", 1)**2 - dt(1)
      sk = 0.5_wp * wmax**2
      sl = 0.5_wp * wmin**2
      yk = sk * jfw - e0
      yl = sl * jfw - e0
      j_end = 1.08_wp * maxval(jr)
      jstep = nice_step(j_end, 5, .false.)
      jhi = jstep * ceiling(j_end / jstep - 1.0e-9_wp)
      ! k and l on the drawing when they lie within three times the range of dT (the machine's
      ! constant inertia far larger than its variable part puts them far off: then the
      ! tangents are drawn over the curve and k, l are given as numbers)
      vmin = min(0.0_wp, minval(dt))
      vmax = max(0.0_wp, maxval(dt))
      on_axis = max(abs(yk), abs(yl)) <= 3.0_wp * (vmax - vmin)
      if (on_axis) then
        vmin = min(vmin, yk, yl, yl + sl * jhi)
        vmax = max(vmax, yk, yl, yk + sk * jhi)
      end if
      step = nice_step(vmax - vmin, 6, .false.)
      lo = step * floor(vmin / step + 1.0e-9_wp)
      hi = step * ceiling(vmax / step - 1.0e-9_wp)
      mu_j = round_scale(jhi, w - 30.0_wp)
      mu_t = round_scale(hi - lo, h - 42.0_wp)
      ! room for the names of k (above it) and l (under it) inside the axes: a step more
      ! where either is within 4 mm of the plot's edge
      do kk = 1, 4
        if (.not. on_axis) exit
        if (yl - lo >= 4.0_wp * mu_t .and. hi - yk >= 4.0_wp * mu_t) exit
        if (yl - lo < 4.0_wp * mu_t) lo = lo - step
        if (hi - yk < 4.0_wp * mu_t) hi = hi + step
        mu_t = round_scale(hi - lo, h - 42.0_wp)
      end do
      q%left = x0 + 22.0_wp
      q%top = y0 + 14.0_wp
      q%width = jhi / mu_j
      q%height = (hi - lo) / mu_t
      q%xlo = 0.0_wp
      q%xhi = jhi
      q%ylo = lo
      q%yhi = hi
      call sheet%set_layer(layer_charts)
      call sheet%rect(x0, y0, w, h, "panel")
      heading = words("Wittenbauer's diagram dT(J_red)", "Диаграмма Виттенбауэра ΔT(J_пр)", lang)
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, heading, "heading")
      call sheet%text(x0 + 2.0_wp, y0 + 10.0_wp, "μJ = "//scale_number(mu_j)//" "//kgm2//"/"//unit_word("mm", lang)// &
        ",  μT = "//scale_number(mu_t)//" "//joule//"/"//unit_word("mm", lang), "small")
      call put_axes(sheet, q%left, q%top, q%width, q%height, 0.0_wp, jhi, jstep, lo, hi, step, &
        words("J_red, ", "J_пр, ", lang)//kgm2, "ΔT, "//joule)
      ! the origin O of the diagram (J = 0, dT = 0)
      ox = q%sx(0.0_wp)
      oy = q%sy(0.0_wp)
      call sheet%circle(ox, oy, 0.8_wp, "origin")
      ! the curve
      call sheet%polyline(q%sx(jr), q%sy(dt), stroke=blue, width=0.45_wp)
      if (jfw <= 0.0_wp) then
        call sheet%place_label("O", "label", ox, oy, 0.75_wp * pi, plot_box(q))
        return
      end if
      ! the tangents from k and l on the dT axis
      ! the tangents dT = y + s J over the plot, clipped to its rectangle
      block
        real(wp) :: ja, jb, yt(2), st(2)
        integer :: t
        yt = [yk, yl]
        st = [sk, sl]
        do t = 1, 2
          ja = 0.0_wp
          jb = jhi
          if (st(t) > 0.0_wp) then
            ja = max(ja, (lo - yt(t)) / st(t))
            jb = min(jb, (hi - yt(t)) / st(t))
          end if
          if (jb > ja) call sheet%line(q%sx(ja), q%sy(yt(t) + st(t) * ja), q%sx(jb), q%sy(yt(t) + st(t) * jb), &
            stroke=red, width=0.3_wp)
        end do
      end block
      if (on_axis) then
        call sheet%line(q%sx(0.0_wp), q%sy(yk), q%sx(0.0_wp), q%sy(yl), stroke=red, width=0.9_wp)
      else
        text = words("k, l off the drawing: dT at k = ", "k, l за пределами чертежа: ΔT в k = ", lang)// &
          short_number(yk)//" "//joule//", "//words("at l = ", "в l = ", lang)//short_number(yl)//" "//joule
        call sheet%text(x0 + 2.0_wp, q%top + q%height + 23.0_wp, text, "small", size=fitted_size(text, 2.4_wp, &
          w - 4.0_wp, 0.62_wp))
      end if
      ! the points of contact
      kk = maxloc(dt - sk * jr, dim=1)
      kl_row = minloc(dt - sl * jr, dim=1)
      call dot(sheet, [q%sx(jr(kk)), q%sy(dt(kk))], red, 0.7_wp)
      call dot(sheet, [q%sx(jr(kl_row)), q%sy(dt(kl_row))], red, 0.7_wp)
      ! the labels when every line is drawn: the origin, k and l (on the J = 0 axis: anywhere
      ! inside the axes, the lines being the obstacles)
      box = [q%left, q%top, q%left + q%width, q%top + q%height]
      call sheet%place_label("O", "label", ox, oy, -0.25_wp * pi, box)
      if (on_axis) then
        call sheet%place_label("k", "label", q%sx(0.0_wp), q%sy(yk), -0.25_wp * pi, box, colour=red)
        call sheet%place_label("l", "label", q%sx(0.0_wp), q%sy(yl), 0.25_wp * pi, box, colour=red)
      end if
      ! the angles of the tangents with the J axis as drawn: tan psi = omega^2/2 * muJ/muT
      psi_k = atan(sk * mu_j / mu_t) * 180.0_wp / pi
      psi_l = atan(sl * mu_j / mu_t) * 180.0_wp / pi
      kl = (yk - yl) / mu_t
      text = "ψ_max = "//fixed_number(psi_k, 2)//"° (omega_max^2/2 · μJ/μT = "//fixed_number(tan(psi_k * pi / 180.0_wp), &
        4)//"),  ψ_min = "//fixed_number(psi_l, 2)//"° (omega_min^2/2 · μJ/μT = "// &
        fixed_number(tan(psi_l * pi / 180.0_wp), 4)//")"
      ! (A4 portrait: the law of the angles, not their tangents, in a line legible at 2.4 mm)
      if (portrait) text = "ψ_max = "//fixed_number(psi_k, 2)//"°,  ψ_min = "//fixed_number(psi_l, 2)//"°  ("// &
        words("tan", "тангенс", lang)//" ψ = omega^2/2 · μJ/μT)"
      call sheet%text(x0 + 2.0_wp, q%top + q%height + 14.0_wp, text, "small", size=fitted_size(text, 2.4_wp, &
        w - 4.0_wp, 0.62_wp))
      text = "k–l = "//fixed_number(kl, 1)//" "//unit_word("mm", lang)//";  J_fw = (k–l)·μT/(δ · omega_m^2) = "// &
        short_number(kl * mu_t / (max(delta, 1.0e-300_wp) * wm**2))//" "//kgm2
      call sheet%text(x0 + 2.0_wp, q%top + q%height + 18.5_wp, text, "small", size=fitted_size(text, 2.4_wp, &
        w - 4.0_wp, 0.62_wp))
    end subroutine wittenbauer

    !> The flywheel in the panel (x0, y0, w, h): its section as a disc of D and b at the
    !> sheet's standard scale, dimensioned, and the table of the dynamics figures.
    subroutine flywheel(x0, y0, w, h)
      real(wp), intent(in) :: x0, y0, w, h
      real(wp) :: d, b, s, cx, cy, dw, bw
      character(len=40) :: cells(13, 2)
      character(len=:), allocatable :: text
      integer :: i
      call sheet%set_layer(layer_charts)
      call sheet%rect(x0, y0, w, h, "panel")
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, words("Flywheel (a disc)", "Маховик (диск)", lang), "heading")
      d = disc_d
      b = disc_b
      if (jfw > 0.0_wp) then
        s = disc_scale%ratio * 1000.0_wp
        dw = d * s
        bw = b * s
        cx = x0 + 0.25_wp * w
        cy = y0 + 0.5_wp * h + 4.0_wp
        call sheet%set_layer(layer_profile)
        call sheet%rect(cx - 0.5_wp * bw, cy - 0.5_wp * dw, bw, dw, "link")
        ! hatching of the section at 45 deg
        do i = -ceiling(dw / 3.0_wp), ceiling(bw / 3.0_wp) + ceiling(dw / 3.0_wp)
          call hatch_line(cx - 0.5_wp * bw, cy - 0.5_wp * dw, bw, dw, 3.0_wp * i)
        end do
        ! the axis (dash-dot) across the disc
        call sheet%line(cx - 0.5_wp * bw - 6.0_wp, cy, cx + 0.5_wp * bw + 6.0_wp, cy, stroke=grey, width=0.18_wp, &
          dash="6 1 1 1")
        call sheet%set_layer(layer_text)
        call put_dimension(sheet, [cx - 0.5_wp * bw, cy + 0.5_wp * dw], [cx - 0.5_wp * bw, cy - 0.5_wp * dw], 8.0_wp, &
          "⌀"//fixed_number(1000.0_wp * d, 0))
        ! (from right to left: a value too wide for the disc goes on the left, away from the table)
        call put_dimension(sheet, [cx + 0.5_wp * bw, cy - 0.5_wp * dw], [cx - 0.5_wp * bw, cy - 0.5_wp * dw], -6.0_wp, &
          fixed_number(1000.0_wp * b, 0))
        text = words("scale ", "масштаб ", lang)//disc_scale%text//", "// &
          words("dimensions in mm", "размеры в мм", lang)
        ! (from the panel's left edge where it is wider than the disc's half of the panel: A4)
        if (fitted_size(text, 2.4_wp, 0.5_wp * w - 4.0_wp, 0.6_wp) < 2.4_wp) then
          call sheet%text(x0 + 2.0_wp, y0 + h - 3.0_wp, text, "small", anchor_start)
        else
          call sheet%text(cx, y0 + h - 3.0_wp, text, "small", anchor_middle)
        end if
      else
        call sheet%text(x0 + 4.0_wp, y0 + 14.0_wp, &
          words("no flywheel: J_flywheel = 0", "маховик не нужен: J_м = 0", lang), "label")
      end if
      cells = ""
      cells(1, :) = [character(len=40) :: words("figure", "величина", lang), words("value", "значение", lang)]
      cells(2, :) = [character(len=40) :: words("M_d, ", "M_д, ", lang)//nm, short_number(md_mean)]
      cells(3, :) = [character(len=40) :: words("J_fw (exact), ", "J_м (точно), ", lang)//kgm2, short_number(jfw)]
      cells(4, :) = [character(len=40) :: words("J_fw (Merzalov), ", "J_м (Мерцалов), ", lang)//kgm2, &
        short_number(table%dynamics%j_flywheel_textbook)]
      cells(5, :) = [character(len=40) :: "δ", short_number(delta)]
      cells(6, :) = [character(len=40) :: "ω_m, "//unit_word("rad/s", lang), short_number(wm)]
      cells(7, :) = [character(len=40) :: "ω_max, "//unit_word("rad/s", lang), short_number(wmax)]
      cells(8, :) = [character(len=40) :: "ω_min, "//unit_word("rad/s", lang), short_number(wmin)]
      cells(9, :) = [character(len=40) :: "D, "//unit_word("m", lang), short_number(d)]
      cells(10, :) = [character(len=40) :: "b = ψD, "//unit_word("m", lang), short_number(b)]
      cells(11, :) = [character(len=40) :: "m, "//unit_word("kg", lang), short_number(disc_m)]
      cells(12, :) = [character(len=40) :: "ρ, "//words("kg/m³", "кг/м³", lang), &
        short_number(table%dynamics%flywheel_density)]
      cells(13, :) = [character(len=40) :: "ψ = b/D", short_number(table%dynamics%flywheel_width_ratio)]
      if (jfw <= 0.0_wp) cells(9:11, 2) = "—"
      call sheet%set_layer(layer_text)
      ! (its rows 4.2 mm apart; A4 portrait: wider, its rows closer)
      if (w < 100.0_wp) then
        call put_table(sheet, x0 + 0.4_wp * w, y0 + 10.0_wp, [0.4_wp * w, 0.18_wp * w], min(4.2_wp, (h - 17.0_wp) / &
          13.0_wp), cells)
      else
        call put_table(sheet, x0 + 0.5_wp * w, y0 + 10.0_wp, [0.3_wp * w, 0.16_wp * w], 4.2_wp, cells)
      end if
    end subroutine flywheel

    !> One hatch line at 45 deg of the rectangle (x, y, w, h), offset `c` along its top edge.
    subroutine hatch_line(x, y, w, h, c)
      real(wp), intent(in) :: x, y, w, h, c
      real(wp) :: ax, ay, bx, by
      ! the line x' - y' = c inside the rectangle (x' from the left, y' from the top, y' down)
      ax = max(0.0_wp, c)
      ay = ax - c
      bx = min(w, c + h)
      by = bx - c
      if (ay > h .or. bx < ax .or. by < 0.0_wp) return
      call sheet%line(x + ax, y + h - ay, x + bx, y + h - by, "hatch")
    end subroutine hatch_line
  end subroutine draw_dynamics_sheet

  !> The header of a course sheet: its heading, the mechanism's name (course_title), the
  !> deck's own title and the --set changes of the run (course_data_line: no file), the
  !> program.
  pure subroutine sheet_header(sheet, title, table, lang, heading)
    type(sheet_t), intent(inout) :: sheet
    character(*), intent(in) :: title
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(*), intent(in) :: heading
    real(wp) :: inner(4), w
    character(len=:), allocatable :: line
    inner = sheet%paper%inside()
    ! right of графа 26 (the designation turned 180 deg in the upper left corner) when given
    inner(1) = inner(1) + header_indent(table)
    w = inner(3) - inner(1) - 12.0_wp
    call sheet%set_layer(layer_text)
    call sheet%text(inner(1) + 6.0_wp, inner(2) + 7.0_wp, heading, "title", size=fitted_size(heading, 4.5_wp, w, 0.8_wp))
    ! (the title often in capitals, Cyrillic ones wider than 0.6 of the size: fitted at 0.72)
    line = course_title(title)
    call sheet%text(inner(1) + 6.0_wp, inner(2) + 12.5_wp, line, "subtitle", size=fitted_size(line, 3.0_wp, w, 0.72_wp), &
      plain=.true.)
    line = course_data_line(table, lang)
    if (len(line) > 0) call sheet%text(inner(1) + 6.0_wp, inner(2) + 17.5_wp, line, "subtitle", &
      size=fitted_size(line, 2.6_wp, w - 30.0_wp, 0.6_wp), plain=.true.)
    call sheet%text(inner(3) - 3.0_wp, inner(2) + 17.5_wp, version_string, "small", anchor_end, plain=.true.)
  end subroutine sheet_header

  !> A chart over the input angle at (x0, y0), `width` wide, its plot at most `hmax` - 26 mm
  !> high: its panel, heading with the scale μ<sym> of the quantity and μφ, axes with y over
  !> `values` (zero included unless `zero` is false) at a round μ, x over `phi` at `mu_phi`.
  pure subroutine put_cycle_chart(sheet, x0, y0, width, hmax, phi, mu_phi, values, unit, sym, heading, xlabel, lang, &
    q, zero)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x0, y0, width, hmax, phi(:), mu_phi, values(:)
    character(*), intent(in) :: unit, sym, heading, xlabel
    integer, intent(in) :: lang
    type(plot_t), intent(out) :: q
    logical, intent(in), optional :: zero
    real(wp) :: lo, hi, step, mu, vmin, vmax, size, two
    character(len=:), allocatable :: text, deg
    logical :: with_zero
    with_zero = .true.
    if (present(zero)) with_zero = zero
    deg = unit_word("deg", lang)
    vmin = minval(values)
    vmax = maxval(values)
    if (with_zero) then
      vmin = min(0.0_wp, vmin)
      vmax = max(0.0_wp, vmax)
    end if
    if (vmax - vmin <= 0.0_wp) vmax = vmin + max(1.0_wp, abs(vmin))
    ! (five steps, fewer on a low chart, A4's: its ticks 5 mm apart at the least)
    step = nice_step(vmax - vmin, max(2, min(5, floor((hmax - 26.0_wp) / 5.0_wp))), .false.)
    lo = step * floor(vmin / step + 1.0e-9_wp)
    hi = step * ceiling(vmax / step - 1.0e-9_wp)
    ! the heading with its scales on one line, or, where that would be smaller than 2.5 mm
    ! (ГОСТ 2.304's smallest but 1.8 mm) and two lines larger, the scales on a second line,
    ! the plot lower by its pitch
    text = heading//";  μ"//sym//" = "//scale_number(mu_of(0.0_wp))//" "//unit//"/"//unit_word("mm", lang)//",  μφ = "// &
      scale_number(mu_phi)//" "//deg//"/"//unit_word("mm", lang)
    size = min(3.0_wp, fitted_size(text, 3.0_wp, width - 4.0_wp, 0.62_wp))
    q%head = 0.0_wp
    if (size < 2.5_wp) then
      two = min(3.0_wp, fitted_size(heading, 3.0_wp, width - 4.0_wp, 0.62_wp), fitted_size(text(len(heading) + 4:), &
        3.0_wp, width - 4.0_wp, 0.62_wp))
      if (two > size) then
        ! (the lines' baselines 2 + 0.9 and 2 + 2.25 sizes under the panel's top, the plot's
        ! top label 2.7 mm under the second: lower than a line's plot where that is below 9 mm)
        size = two
        q%head = max(0.0_wp, 2.25_wp * size - 4.3_wp)
      end if
    end if
    mu = mu_of(q%head)
    q%left = x0 + 19.0_wp
    q%top = y0 + 9.0_wp + q%head
    q%width = (maxval(phi) - minval(phi)) / mu_phi
    q%height = (hi - lo) / mu
    q%xlo = minval(phi)
    q%xhi = maxval(phi)
    q%ylo = lo
    q%yhi = hi
    call sheet%set_layer(layer_charts)
    call sheet%rect(x0, y0, width, q%height + 24.0_wp + q%head, "panel")
    text = heading//";  μ"//sym//" = "//scale_number(mu)//" "//unit//"/"//unit_word("mm", lang)//",  μφ = "// &
      scale_number(mu_phi)//" "//deg//"/"//unit_word("mm", lang)
    if (size > min(3.0_wp, fitted_size(text, 3.0_wp, width - 4.0_wp, 0.62_wp))) then
      call sheet%text(x0 + 2.0_wp, y0 + 2.0_wp + 0.9_wp * size, heading//";", "heading", size=size)
      call sheet%text(x0 + 2.0_wp, y0 + 2.0_wp + 2.25_wp * size, text(len(heading) + 4:), "heading", size=size)
    else
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, text, "heading", size=size)
    end if
    call put_axes(sheet, q%left, q%top, q%width, q%height, q%xlo, q%xhi, nice_step(q%xhi - q%xlo, 8, .true.), lo, hi, &
      step, xlabel, unit)
  contains
    !> The chart's round μ of the quantity with its plot `drop` mm lower.
    pure real(wp) function mu_of(drop)
      real(wp), intent(in) :: drop
      mu_of = round_scale(hi - lo, hmax - 26.0_wp - drop)
    end function mu_of
  end subroutine put_cycle_chart

  !> A curve over the input angle `phi` in the plot q with its name placed beside it.
  pure subroutine put_cycle_curve(sheet, q, phi, v, colour, dash, name)
    type(sheet_t), intent(inout) :: sheet
    type(plot_t), intent(in) :: q
    real(wp), intent(in) :: phi(:), v(:)
    character(*), intent(in) :: colour, dash, name
    real(wp), allocatable :: sx(:), sy(:)
    integer :: k
    allocate (sx(size(v)), sy(size(v)))
    sx = q%sx(phi(:size(v)))
    sy = q%sy(v)
    call sheet%polyline(sx, sy, stroke=colour, width=0.45_wp, dash=dash)
    k = max(1, nint(0.62_wp * size(v)))
    call sheet%place_label(name, "label", sx(k), sy(k), -0.5_wp * pi, plot_box(q), colour=colour)
  end subroutine put_cycle_curve

  !> The plot's rectangle less 1 mm: where its labels may go.
  pure function plot_box(q) result(b)
    type(plot_t), intent(in) :: q
    real(wp) :: b(4)
    b = [q%left + 1.0_wp, q%top + 1.0_wp, q%left + q%width - 1.0_wp, q%top + q%height - 1.0_wp]
  end function plot_box

  !> x on the sheet of an abscissa value, mm.
  elemental real(wp) function plot_x(self, x)
    class(plot_t), intent(in) :: self
    real(wp), intent(in) :: x
    plot_x = self%left + self%width * (x - self%xlo) / (self%xhi - self%xlo)
  end function plot_x

  !> y on the sheet of an ordinate value, mm.
  elemental real(wp) function plot_y(self, y)
    class(plot_t), intent(in) :: self
    real(wp), intent(in) :: y
    plot_y = self%top + self%height - self%height * (y - self%ylo) / (self%yhi - self%ylo)
  end function plot_y

end module kinetostat_dynamics_sheet
