!> Languages of the legacy table and the labels shared by every mechanism's table.
!> English is the program's own wording; Russian follows the 1991 printouts
!> (ИСХОДНЫЕ ДАННЫЕ, РЕЗУЛЬТАТЫ РАСЧЕТА, ...). Mechanism-specific headings live in each
!> mechanism's layout module.
module kinetostat_labels
  use kinetostat_text, only: starts_with, replace_all
  implicit none
  private
  public :: lang_en, lang_ru, lang_names, lang_from_name, label, phrase, echo_name, unit_symbol, in_language

  !> Language: English (default).
  integer, parameter :: lang_en = 1
  !> Language: Russian (UTF-8).
  integer, parameter :: lang_ru = 2
  !> The languages' names as --lang takes them, in the order of their codes.
  character(*), parameter :: lang_names(*) = [character(len=2) :: "en", "ru"]

  ! The tables of wordings below: an entry is "english=>russian"; the Russian wording ends in
  ! as many blanks as the English one (the entries are blank-padded to one length).

  !> The shared labels in Russian (label).
  character(*), parameter :: label_words(*) = [character(len=360) :: &
    "INPUT DATA=>ИСХОДНЫЕ ДАННЫЕ", &
    "RESULTS=>РЕЗУЛЬТАТЫ РАСЧЕТА", &
    "DECK: =>ФАЙЛ ДАННЫХ:", &
    "TITLE: =>НАЗВАНИЕ:", &
    "SELF-CHECK (relative; limit =>САМОКОНТРОЛЬ (ОТНОСИТЕЛЬНЫЕ "// &
      "ВЕЛИЧИНЫ; ДОПУСК", &
    "MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS=>НАИБ. НЕВЯЗКА РАВНОВЕСИЯ ПО "// &
      "ВСЕМ ЗВЕНЬЯМ И ПОЛОЖЕНИЯМ", &
    "MAX EQUILIBRIUM RESIDUAL OF THE FOLLOWER, ALL STEPS=>НАИБ. НЕВЯЗКА РАВНОВЕСИЯ "// &
      "ТОЛКАТЕЛЯ ПО ВСЕМ ПОЛОЖЕНИЯМ", &
    "MAX N MISMATCH, CLOSED FORM VS 3X3 LINEAR SOLVE=>НАИБ. РАСХОЖДЕНИЕ N: ФОРМУЛА "// &
      "И РЕШЕНИЕ СИСТЕМЫ 3X3", &
    "SUMMARY=>СВОДКА", &
    ! the design kinds (gear pair, cam): their summary block and self-check
    "SIZE OF THE CAM=>РАЗМЕРЫ КУЛАЧКА", &
    "THETA OVER ITS LIMIT (RELATIVE), ALL STEPS=>ПРЕВЫШЕНИЕ ДОПУСТИМОГО УГЛА "// &
      "ДАВЛЕНИЯ (ОТНОС.)", &
    "RHO BELOW RHO_MIN (RELATIVE), ALL STEPS=>RHO МЕНЬШЕ RHO_MIN (ОТНОС.), ВСЕ ПОЛОЖЕНИЯ", &
    "CURVATURE: TWO FORMULAS (X R_PRIME), ALL STEPS=>КРИВИЗНА ПО ДВУМ ФОРМУЛАМ (X "// &
      "R_PRIME), ВСЕ ПОЛОЖЕНИЯ", &
    "INV(ALPHA_W) AGAINST ITS EQUATION=>INV(ALPHA_W): НЕВЯЗКА УРАВНЕНИЯ", &
    "EPS_ALPHA: FORMULA VS THE PATH OF CONTACT'S ENDS=>EPS_ALPHA: ФОРМУЛА И КОНЦЫ "// &
      "АКТИВНОЙ ЛИНИИ ЗАЦЕПЛЕНИЯ", &
    "(derived)=>(вычислено)", &
    "SHAKING FORCE AND MOMENT, FORCE AND MOMENT ON THE FRAME (MOMENTS ABOUT THE ORIGIN)=>ГЛАВНЫЙ "// &
      "ВЕКТОР И ГЛАВНЫЙ МОМЕНТ СИЛ ИНЕРЦИИ, СИЛА И МОМЕНТ НА "// &
      "СТОЙКУ (МОМЕНТЫ ОТНОСИТЕЛЬНО НАЧАЛА КООРДИНАТ)", &
    "MAX=>НАИБ", &
    "MIN=>НАИМ", &
    "STEPS LEFT OUT=>ПОЛОЖЕНИЙ ИСКЛ.", &
    "JAMMED OR LOST CONTACT: NO FORCES, NOT IN MAX, MIN, MEAN=>ЗАКЛИНИВАНИЕ ИЛИ "// &
      "ПОТЕРЯ КОНТАКТА: СИЛ НЕТ, НЕ В МАКС., МИН., СРЕДН.", &
    "MEAN=>СРЕДН", &
    "AT =>ПРИ", &
    "WORK OF =>РАБОТА", &
    ! friction in the pairs of the generic engine (summary block and self-check)
    "WORK AND EFFICIENCY WITH FRICTION=>РАБОТА И КПД С УЧЕТОМ ТРЕНИЯ", &
    "ETA = 1 - A_LOSS/A_DRIVER OVER A WHOLE TURN OF THE INPUT: THE CYCLE EFFICIENCY=>ETA = 1 - "// &
      "A_LOSS/A_DRIVER ЗА ПОЛНЫЙ ОБОРОТ ВХОДНОГО ЗВЕНА: ЦИКЛОВОЙ КПД", &
    "ETA = 1 - A_LOSS/A_DRIVER OVER LESS THAN A WHOLE TURN: NOT THE CYCLE EFFICIENCY=>ETA = 1 - "// &
      "A_LOSS/A_DRIVER МЕНЕЕ ЧЕМ ЗА ОБОРОТ: НЕ ЦИКЛОВОЙ КПД", &
    "(THE DRIVER'S WORK ALSO CHANGES THE KINETIC AND POTENTIAL ENERGY)=>(РАБОТА ДВИГАТЕЛЯ "// &
      "ИДЕТ ТАКЖЕ НА ИЗМЕНЕНИЕ КИНЕТИЧЕСКОЙ И ПОТЕНЦИАЛЬНОЙ "// &
      "ЭНЕРГИИ)", &
    "ETA NOT DEFINED: THE DRIVER DELIVERS NO NET WORK OVER THE RUN=>КПД НЕ ОПРЕДЕЛЕН: "// &
      "РАБОТА ДВИГАТЕЛЯ ЗА РАСЧЕТ НЕ ПОЛОЖИТЕЛЬНА", &
    "MAX EQUILIBRIUM RESIDUAL WITH FRICTION LOADS=>НАИБ. НЕВЯЗКА РАВНОВЕСИЯ С "// &
      "СИЛАМИ ТРЕНИЯ", &
    "MAX M1 MISMATCH, POWER BALANCE WITH FRICTION=>НАИБ. РАСХОЖДЕНИЕ M1, БАЛАНС "// &
      "МОЩНОСТЕЙ С ТРЕНИЕМ", &
    "MAX F_drive MISMATCH, POWER BALANCE WITH FRICTION=>НАИБ. РАСХОЖДЕНИЕ F_drive, "// &
      "БАЛАНС МОЩНОСТЕЙ С ТРЕНИЕМ", &
    ! machine dynamics (the DYNAMICS block and its self-check line)
    "DYNAMICS (REDUCED TO THE INPUT LINK)=>ДИНАМИЧЕСКИЙ РАСЧЕТ (ПРИВЕДЕНИЕ "// &
      "К ВХОДНОМУ ЗВЕНУ)", &
    "MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE WITH FRICTION=>НАИБ. РАСХОЖДЕНИЕ "// &
      "УСИЛИЙ ПРИВОДОВ С БАЛАНСОМ МОЩНОСТЕЙ С ТРЕНИЕМ", &
    "MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE=>НАИБ. РАСХОЖДЕНИЕ УСИЛИЙ "// &
      "ПРИВОДОВ С БАЛАНСОМ МОЩНОСТЕЙ", &
    "MAX |M1 - M_d|/|M_d| WITH THE TRUE MOTION=>НАИБ. |M1 - M_d|/|M_d| ПРИ ИСТИННОМ "// &
      "ДВИЖЕНИИ", &
    "M_d=>M_d (ДВИЖУЩИЙ МОМЕНТ)", &
    "J_flywheel=>МАХОВИК J_flywheel", &
    "flywheel_density=>МАХОВИК: ПЛОТНОСТЬ", &
    "flywheel_width_ratio=>МАХОВИК: b/D", &
    "flywheel_D=>МАХОВИК: ДИАМЕТР D", &
    "flywheel_b=>МАХОВИК: ШИРИНА b", &
    "flywheel_m=>МАХОВИК: МАССА m", &
    "flywheel_note=>МАХОВИК", &
    "a disc: J_flywheel = m D^2/8, m = density pi D^2 b/4, b = width_ratio D=>ДИСК: J_flywheel = m "// &
      "D^2/8, m = ПЛОТНОСТЬ pi D^2 b/4, b = (b/D) D", &
    "no flywheel: J_flywheel = 0=>МАХОВИКА НЕТ: J_flywheel = 0", &
    "none=>НЕТ", &
    "kg/m^3=>кг/м^3", &
    "J_flywheel_textbook=>МАХОВИК ПО МЕРЦАЛОВУ", &
    "textbook_difference=>РАЗНИЦА С МЕРЦАЛОВЫМ", &
    "J_rotor=>J_rotor (РОТОР)", &
    "J_red_min=>ПРИВЕДЕННЫЙ МОМЕНТ ИНЕРЦИИ НАИМ", &
    "J_red_max=>ПРИВЕДЕННЫЙ МОМЕНТ ИНЕРЦИИ НАИБ", &
    "omega_mean=>omega СРЕДНЯЯ", &
    "omega_max=>omega НАИБ", &
    "phi_omega_max=>phi ПРИ omega НАИБ", &
    "omega_min=>omega НАИМ", &
    "phi_omega_min=>phi ПРИ omega НАИМ", &
    "delta=>КОЭФФ. НЕРАВНОМЕРНОСТИ delta", &
    "delta_asked=>delta ЗАДАННЫЙ", &
    "period=>ПЕРИОД ЦИКЛА", &
    "%=>%", &
    "s=>с", &
    ! units (ГОСТ symbols, as the 1991 printouts write them)
    "J=>Дж", &
    "m=>м", &
    "mm=>мм", &
    "kg=>кг", &
    "kg*m^2=>кг*м^2", &
    "N=>Н", &
    "N*m=>Н*м", &
    "deg=>град", &
    "rad/s=>рад/с", &
    "rad/s^2=>рад/с^2", &
    "m/s^2=>м/с^2", &
    "m/rad=>м/рад", &
    "m/rad^2=>м/рад^2", &
    "1/rad=>1/рад", &
    "steps=>положений", &
    "satellites=>сателлитов", &
    "rad=>рад", &
    "m/s=>м/с", &
    "W=>Вт", &
    ! the words of the SVG sheets (the course's wording: план скоростей, план сил, рычаг Жуковского)
    "deck=>файл данных", &
    "step=>положение", &
    "stage=>ступень", &
    "stages=>ступеней", &
    "of=>из", &
    "at=>под углом", &
    "gravity down the sheet=>сила тяжести вниз по листу", &
    "lengths=>длины", &
    "forces=>силы", &
    "pair force=>реакция", &
    "load=>нагрузка", &
    "weight=>вес", &
    "inertia=>инерция", &
    "Forces of the step (angles counterclockwise from the x axis of the mechanism's frame)=>Силы "// &
      "положения (углы против часовой стрелки от оси x "// &
      "системы координат механизма)", &
    "Hodographs of the pair forces=>Годографы реакций в кинематических парах", &
    "Tip of each force vector over the cycle, in the frame of the tables (x right, y up); point k = step "// &
      "k; O = zero force.=>Конец вектора каждой силы за цикл в системе "// &
      "координат таблиц (x вправо, y вверх); точка k = положение "// &
      "k; O = нулевая сила.", &
    "Pair forces of every stage as vectors=>Реакции каждой ступени как векторы", &
    "The rows of this table are stages, not steps of a cycle: no hodographs and no diagrams against an "// &
      "input angle.=>Строки этой таблицы - ступени, а не положения "// &
      "цикла: ни годографов, ни диаграмм по углу входного "// &
      "звена.", &
    "This table has no pair force with an angle column: no hodographs.=>В таблице нет "// &
      "реакций со столбцом угла: годографов нет.", &
    "max=>наиб.", &
    "mean=>среднее", &
    "Driving effort=>Движущее усилие", &
    "This table has no driving moment or force column.=>В таблице нет столбца "// &
      "движущего момента или силы.", &
    "Driving force=>Движущая сила", &
    "Driving moment=>Движущий момент", &
    "against=>по", &
    "Magnitudes of the pair forces against=>Модули реакций по", &
    "No pair forces to show.=>Реакций для показа нет.", &
    "force=>сила", &
    "no pair force=>нет реакций", &
    "at every step=>во всех положениях", &
    "Plan of velocities=>План скоростей", &
    "Plan of accelerations=>План ускорений", &
    "Zhukovsky's lever=>Рычаг Жуковского", &
    "plan of velocities turned by 90 deg=>план скоростей, повернутый на 90 град", &
    "Force polygons of the links=>Планы сил звеньев", &
    "link=>звено", &
    "Machine dynamics (reduced to the input link)=>Динамика машины (приведение "// &
      "к входному звену)", &
    "Steady cycle=>Установившийся режим", &
    "flywheel=>маховик", &
    "textbook=>по учебнику", &
    "Reduced moment of inertia J_red=>Приведенный момент инерции J_red", &
    "Reduced moment M_red and M_d (dashed)=>Приведенный момент M_red и M_d (штрих)", &
    "Change of kinetic energy dT=>Изменение кинетической энергии dT", &
    "Speed omega1 (dashed: mean, max, min)=>Скорость omega1 (штрих: средн., наиб., "// &
      "наим.)", &
    "Wittenbauer's curve: dT against J_red=>Кривая Виттенбауэра: dT по J_red", &
    "Force polygons=>Планы сил", &
    "balancing effort from the lever=>уравновешивающее усилие по рычагу", &
    "analytic value of the step=>аналитическое значение в положении", &
    "relative difference=>относительное расхождение", &
    "flywheel and rotor included=>маховик и ротор учтены", &
    "pair friction included=>трение в парах учтено", &
    "not drawn=>не построен", &
    "arrows: directions of the loads=>стрелки: направления нагрузок", &
    "known forces first, then the pair forces=>сначала известные силы, затем "// &
      "реакции", &
    "no driver column=>нет столбца движущего усилия", &
    "the driving link is at rest=>ведущее звено неподвижно", &
    "the driver is not a moment on a link of the drawing=>движущее усилие - не "// &
      "момент на звене чертежа", &
    "the driver is neither a moment on a link nor a force on a slider of the drawing=>движущее "// &
      "усилие - ни момент на звене, ни сила на ползуне чертежа", &
    "Force polygons of the groups=>Планы сил групп", &
    "Assur group=>группа", &
    "input link=>входное звено", &
    "through the joint=>через шарнир", &
    "the group apart=>группа отдельно", &
    "known forces first, then the unknown reactions=>сначала известные силы, "// &
      "затем искомые реакции", &
    "Mechanism=>Механизм", &
    "position=>положение", &
    "the plans in the mechanism's frame=>планы в системе координат чертежа "// &
      "механизма", &
    "Loads on the lever=>Нагрузки на рычаге", &
    "image=>точка плана", &
    "arms on the lever=>плечи на рычаге", &
    "Values read off the plans=>Величины по планам", &
    "counterclockwise=>против часовой стрелки", &
    "clockwise=>по часовой стрелке", &
    "at the pole=>в полюсе", &
    "not drawn, shorter than 1 mm=>не показаны, короче 1 мм", &
    "Balancing effort=>Уравновешивающее усилие", &
    "read off the sheet (vectors to 0.5 mm, arms to 1 mm)=>по чертежу (векторы с "// &
      "точностью 0,5 мм, плечи 1 мм)", &
    "lever=>рычаг", &
    "polygons=>планы сил", &
    "relative velocities: v_PQ of a link's points, r along a guide=>относительные "// &
      "скорости: v_PQ точек звена, r вдоль направляющей", &
    "components: n normal, τ tangential, k Coriolis, r relative=>составляющие: n норм., "// &
      "τ касат., k кориол., r относит.", &
    "Plans of velocities, accelerations, forces=>Планы скоростей, ускорений, сил", &
    "Mechanism with its forces=>Механизм с силами", &
    "Force analysis of the mechanism=>Силовой расчет механизма", &
    "drawn at the link's point, its line of action=>приложена к точке звена, "// &
      "её линия действия в", &
    "from it (off the drawing)=>от неё (вне чертежа)", &
    "Hodographs and diagrams=>Годографы и диаграммы", &
    "not drawn, shorter than 1 mm at μF=>не показаны, короче 1 мм при μF", &
    "under 1 mm, not drawn=>короче 1 мм, не показаны", &
    "The input step=>Шаг входного звена", &
    "is coarser than=>крупнее", &
    "next to a load that switches on or off=>рядом с включением или "// &
      "выключением нагрузки", &
    "the curves join the steps by chords and may miss the true peaks and the true mean; rerun with a "// &
      "finer step=>кривые соединяют положения хордами и могут "// &
      "пропустить истинные максимумы и истинное среднее; "// &
      "повторите расчет с меньшим шагом", &
    "points drawn=>точек показано", &
    "Shaking force and moment (the resultant of the inertia forces)=>Главный вектор и "// &
      "главный момент сил инерции", &
    "Shaking moment=>Главный момент сил инерции"]

  !> The notes in parentheses after a unit or a value in Russian (note).
  character(*), parameter :: note_words(*) = [character(len=360) :: &
    "frame 1=>система 1", &
    "frame 2=>система 2", &
    "rise; derived=>подъем; вычислено", &
    "along +x2=>вдоль +x2", &
    "from forces=>из сил", &
    "power balance=>баланс мощностей", &
    "carrier, from forces=>водило, из сил", &
    "on the ring, from forces=>на коронном колесе, из сил", &
    "echoed below as derived link coordinates=>ниже - пересчитанные "// &
      "координаты звеньев", &
    "derived=>вычислено"]

  !> The words of the echo's composite names ("STAGE 1: SPUR", "DYAD 1: RRR LINKS 2-3, ON
  !> LINKS 1 AND 0, MODE 1", "FORCE 2 LINK"), replaced in this order (echo_name).
  character(*), parameter :: composite_words(*) = [character(len=360) :: &
    "STAGE =>СТУПЕНЬ", &
    ": SPUR=>: ПРЯМОЗУБАЯ", &
    ": HELICAL=>: КОСОЗУБАЯ", &
    ": BEVEL=>: КОНИЧЕСКАЯ", &
    ": PLANETARY=>: ПЛАНЕТАРНАЯ", &
    "DYAD =>ДИАДА", &
    " ON LINKS => НА ЗВЕНЬЯХ", &
    " LINKS => ЗВЕНЬЯ", &
    " AND => И", &
    ", MODE =>, СБОРКА", &
    "FORCE =>СИЛА", &
    "MOMENT =>МОМЕНТ", &
    " LINK=> ЗВЕНО"]

  !> The words of a gear stage's torques (echo_name).
  character(*), parameter :: torque_words(*) = [character(len=360) :: &
    " POWER=> МОЩН.", &
    " HOUSING=> КОРПУСА", &
    " BALANCE=> БАЛАНС"]

  !> The words of a general linkage's echo lines, replaced in this order before a dyad's
  !> kind is put in the course's letters (linkage_echo_ru).
  character(*), parameter :: linkage_words(*) = [character(len=360) :: &
    "STRUCTURAL ANALYSIS=>СТРУКТУРНЫЙ АНАЛИЗ", &
    "MOVING LINKS n=>ПОДВИЖНЫХ ЗВЕНЬЕВ n", &
    "LOWER PAIRS p5=>НИЗШИХ ПАР p5", &
    "HIGHER PAIRS p4=>ВЫСШИХ ПАР p4", &
    "NUMBER OF DRIVES=>ЧИСЛО НАЧАЛЬНЫХ ЗВЕНЬЕВ", &
    "STRUCTURE FORMULA:=>ФОРМУЛА СТРОЕНИЯ:", &
    "CLASS OF THE MECHANISM:=>КЛАСС МЕХАНИЗМА:", &
    "INPUT LINK(S) (MECHANISM OF CLASS I)=>НАЧАЛЬНОЕ ЗВЕНО (МЕХАНИЗМ I КЛАССА)"]

  !> The same after the dyad's kind (linkage_echo_ru).
  character(*), parameter :: linkage_unit_words(*) = [character(len=360) :: &
    "DYAD (GROUP OF CLASS II, ORDER 2), KIND=>ДИАДА (ГРУППА II КЛАССА 2-ГО "// &
      "ПОРЯДКА), ВИД", &
    "GROUP OF CLASS III, ORDER 3=>ГРУППА III КЛАССА 3-ГО ПОРЯДКА", &
    "GROUP OF CLASS III, ORDER 4=>ГРУППА III КЛАССА 4-ГО ПОРЯДКА", &
    "(TWO TERNARY BASE LINKS AND FOUR BINARY LINKS)=>(ДВА БАЗОВЫХ ЗВЕНА С ТРЕМЯ ПАРАМИ)", &
    "(A TERNARY BASE LINK AND THREE BINARY LINKS)=>(БАЗОВОЕ ЗВЕНО С ТРЕМЯ ПАРАМИ)", &
    "GROUP OF CLASS IV, ORDER 2=>ГРУППА IV КЛАССА 2-ГО ПОРЯДКА", &
    "(A CLOSED FOUR-LINK CONTOUR)=>(ЗАМКНУТЫЙ ЧЕТЫРЕХЗВЕННЫЙ КОНТУР)", &
    "(CLASS NOT DETERMINED)=>(КЛАСС НЕ ОПРЕДЕЛЕН)", &
    "GROUP OF =>ГРУППА ИЗ", &
    ", FOLLOWS THE LINK=>, ПОВОРАЧИВАЕТСЯ СО ЗВЕНОМ", &
    ", GUIDE ON =>, НАПРАВЛЯЮЩАЯ НА ЗВЕНЕ", &
    ", INPUT =>, ВХОД", &
    ", EFFORT =>, УСИЛИЕ", &
    "DRIVE =>ПРИВОД", &
    "PAIR =>ПАРА", &
    "FORCE =>СИЛА", &
    "MOMENT =>МОМЕНТ", &
    " LINKS (=> ЗВЕНЬЕВ (", &
    " LINKS => ЗВЕНЬЯ", &
    " LINKS=> ЗВЕНЬЕВ", &
    " AND => И", &
    "LINK =>ЗВЕНО"]

contains

  !> Language code from its name ("en", "ru"); 0 when unknown.
  pure integer function lang_from_name(name)
    !> Name given with --lang.
    character(*), intent(in) :: name
    lang_from_name = findloc(lang_names, name, dim=1)
  end function lang_from_name

  !> A shared label in language `lang`; `english` is both the key and the English text.
  pure function label(english, lang) result(text)
    !> The English label (key).
    character(*), intent(in) :: english
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    if (lang == lang_ru) then
      text = translated(english, label_words)
    else
      text = english
    end if
  end function label

  !> A unit symbol for a drawing in language `lang`: the table's symbol (Н*м, кг*м^2) with the
  !> typographic dot and superscript (Н·м, кг·м²); unknown units as they are.
  pure function unit_symbol(unit, lang) result(text)
    !> The unit as the tables write it ("N", "N*m", "deg").
    character(*), intent(in) :: unit
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = in_language(unit, replace_all(replace_all(label(unit, lang), "*", "·"), "^2", "²"), lang)
  end function unit_symbol

  !> A phrase of the legacy table in language `lang`: a shared label; a unit with a note
  !> ("deg (frame 1)"); the echo's composite names and headings ("FORCE 2 LINK",
  !> "STAGE 1: SPUR", "DYAD 1: RRR LINKS 2-3, ON LINKS 1 AND 0, MODE 1"). Symbols and
  !> deck values stay as they are; anything else is returned unchanged.
  pure function phrase(english, lang) result(text)
    !> The English phrase.
    character(*), intent(in) :: english
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    integer :: open_paren
    text = english
    if (lang /= lang_ru) return
    text = label(english, lang)
    if (text /= english) return
    open_paren = index(english, " (")
    if (open_paren > 0 .and. len(english) > open_paren + 2) then
      if (english(len(english):) == ")") then
        text = phrase(english(:open_paren - 1), lang)//" ("//note(english(open_paren + 2:len(english) - 1))//")"
        return
      end if
    end if
    text = echo_name(english, lang)
  end function phrase

  !> The name of an INPUT DATA record or an echo heading in language `lang`: the composite
  !> names ("FORCE 2 LINK", "STAGE 1: SPUR", "DYAD 1: RRR LINKS 2-3, ON LINKS 1 AND 0, MODE 1")
  !> translated; a deck variable's name ("PHI_START", "N") stays as it is.
  pure function echo_name(english, lang) result(text)
    !> The English name, as the deck or the layout spells it.
    character(*), intent(in) :: english
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = english
    if (lang /= lang_ru) return
    if (index(english, "STAGE ") == 1 .or. index(adjustl(english), "DYAD ") == 1 .or. &
      (index(english, "FORCE ") == 1 .or. index(english, "MOMENT ") == 1) .and. index(english, " LINK") > 0) then
      call replace_words(text, composite_words)
    else if (is_linkage_echo(adjustl(english))) then
      text = linkage_echo_ru(english)
    else if (index(english, "M") == 1 .and. (index(english, " POWER") > 0 .or. index(english, " HOUSING") > 0 .or. &
      index(english, " BALANCE") > 0)) then
      ! a gear stage's torques: from the power balance, on the housing, from the torque balance
      call replace_words(text, torque_words)
    end if
  end function echo_name

  !> Whether an echo line is one of a general linkage's (&linkage): its links, pairs, drives,
  !> loads and the structural analysis.
  pure logical function is_linkage_echo(text)
    !> The line without leading blanks.
    character(*), intent(in) :: text
    is_linkage_echo = starts_with(text, "LINK ") .or. starts_with(text, "PAIR ") .or. &
      starts_with(text, "DRIVE ") .or. starts_with(text, "FORCE ") .or. starts_with(text, "MOMENT ") .or. &
      starts_with(text, "STRUCTURAL ANALYSIS") .or. starts_with(text, "MOVING LINKS n =") .or. &
      starts_with(text, "W = 3n") .or. starts_with(text, "STRUCTURE FORMULA:") .or. &
      starts_with(text, "CLASS OF THE MECHANISM:")
    ! a structural unit: "II(2,3)  DYAD (GROUP OF CLASS II, ORDER 2), KIND RRR"
    if (index(text, "  INPUT LINK(S)") > 0 .or. index(text, "  DYAD (GROUP") > 0 .or. &
        index(text, "  GROUP OF ") > 0) is_linkage_echo = .true.
  end function is_linkage_echo

  !> A dyad's kind in the Russian course's letters: RRP -> ВВП (R a turning pair, В; P a
  !> sliding pair, П); other characters as they are.
  pure function course_kind(kind) result(text)
    !> The kind as the program writes it ("RRP").
    character(*), intent(in) :: kind
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, len(kind)
      select case (kind(i:i))
      case ("R")
        text = text//"В"
      case ("P")
        text = text//"П"
      case default
        text = text//kind(i:i)
      end select
    end do
  end function course_kind

  !> A general linkage's echo line in Russian, in the words of kinetostat structure --lang ru.
  pure function linkage_echo_ru(english) result(text)
    !> The English line.
    character(*), intent(in) :: english
    character(len=:), allocatable :: text
    integer :: k
    text = english
    call replace_words(text, linkage_words)
    ! a dyad's kind in the course's letters: В (вращательная) for R, П (поступательная) for P
    k = index(text, "), KIND ")
    if (k > 0) text = text(1:k + 7)//course_kind(text(k + 8:))
    call replace_words(text, linkage_unit_words)
  end function linkage_echo_ru

  !> A note in parentheses after a unit or a value, in Russian (unknown notes unchanged).
  pure function note(english) result(text)
    character(*), intent(in) :: english
    character(len=:), allocatable :: text
    text = translated(english, note_words)
  end function note

  !> `english` or, with lang_ru, `russian`: a text given in both wordings side by side.
  pure function in_language(english, russian, lang) result(text)
    character(*), intent(in) :: english, russian
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    if (lang == lang_ru) then
      text = russian
    else
      text = english
    end if
  end function in_language

  !> The Russian wording of `english` in `words` (entries "english=>russian"), or `english`
  !> when it has none there.
  pure function translated(english, words) result(text)
    !> The English wording.
    character(*), intent(in) :: english
    !> The table of wordings.
    character(*), intent(in) :: words(:)
    character(len=:), allocatable :: text
    integer :: i
    text = english
    do i = 1, size(words)
      if (words(i)(1:index(words(i), "=>") - 1) /= english) cycle
      text = russian_of(words(i))
      return
    end do
  end function translated

  !> Replace in `text` the English wording of every entry of `words` ("english=>russian") by
  !> its Russian one, in the table's order.
  pure subroutine replace_words(text, words)
    !> The text, English on entry.
    character(len=:), allocatable, intent(inout) :: text
    !> The table of wordings.
    character(*), intent(in) :: words(:)
    integer :: i
    do i = 1, size(words)
      text = replace_all(text, english_of(words(i)), russian_of(words(i)))
    end do
  end subroutine replace_words

  !> The English wording of an entry "english=>russian".
  pure function english_of(entry) result(text)
    character(*), intent(in) :: entry
    character(len=:), allocatable :: text
    text = entry(1:index(entry, "=>") - 1)
  end function english_of

  !> The Russian wording of an entry "english=>russian", with as many trailing blanks as the
  !> English wording.
  pure function russian_of(entry) result(text)
    character(*), intent(in) :: entry
    character(len=:), allocatable :: text
    integer :: arrow
    arrow = index(entry, "=>")
    text = trim(entry(arrow + 2:))//repeat(" ", arrow - 1 - len_trim(entry(1:arrow - 1)))
  end function russian_of

end module kinetostat_labels
