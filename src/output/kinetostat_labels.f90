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
    text = english
    if (lang /= lang_ru) return
    select case (english)
    case ("INPUT DATA")
      text = "ИСХОДНЫЕ ДАННЫЕ"
    case ("RESULTS")
      text = "РЕЗУЛЬТАТЫ РАСЧЕТА"
    case ("DECK: ")
      text = "ФАЙЛ ДАННЫХ: "
    case ("TITLE: ")
      text = "НАЗВАНИЕ: "
    case ("SELF-CHECK (relative; limit ")
      text = "САМОКОНТРОЛЬ (ОТНОСИТЕЛЬНЫЕ ВЕЛИЧИНЫ; ДОПУСК "
    case ("MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS")
      text = "НАИБ. НЕВЯЗКА РАВНОВЕСИЯ ПО ВСЕМ ЗВЕНЬЯМ И ПОЛОЖЕНИЯМ"
    case ("MAX EQUILIBRIUM RESIDUAL OF THE FOLLOWER, ALL STEPS")
      text = "НАИБ. НЕВЯЗКА РАВНОВЕСИЯ ТОЛКАТЕЛЯ ПО ВСЕМ ПОЛОЖЕНИЯМ"
    case ("MAX N MISMATCH, CLOSED FORM VS 3X3 LINEAR SOLVE")
      text = "НАИБ. РАСХОЖДЕНИЕ N: ФОРМУЛА И РЕШЕНИЕ СИСТЕМЫ 3X3"
    case ("SUMMARY")
      text = "СВОДКА"
    ! the design kinds (gear pair, cam): their summary block and self-check
    case ("SIZE OF THE CAM")
      text = "РАЗМЕРЫ КУЛАЧКА"
    case ("THETA OVER ITS LIMIT (RELATIVE), ALL STEPS")
      text = "ПРЕВЫШЕНИЕ ДОПУСТИМОГО УГЛА ДАВЛЕНИЯ (ОТНОС.)"
    case ("RHO BELOW RHO_MIN (RELATIVE), ALL STEPS")
      text = "RHO МЕНЬШЕ RHO_MIN (ОТНОС.), ВСЕ ПОЛОЖЕНИЯ"
    case ("CURVATURE: TWO FORMULAS (X R_PRIME), ALL STEPS")
      text = "КРИВИЗНА ПО ДВУМ ФОРМУЛАМ (X R_PRIME), ВСЕ ПОЛОЖЕНИЯ"
    case ("INV(ALPHA_W) AGAINST ITS EQUATION")
      text = "INV(ALPHA_W): НЕВЯЗКА УРАВНЕНИЯ"
    case ("EPS_ALPHA: FORMULA VS THE PATH OF CONTACT'S ENDS")
      text = "EPS_ALPHA: ФОРМУЛА И КОНЦЫ АКТИВНОЙ ЛИНИИ ЗАЦЕПЛЕНИЯ"
    case ("(derived)")
      text = "(вычислено)"
    case ("SHAKING FORCE AND MOMENT, FORCE AND MOMENT ON THE FRAME (MOMENTS ABOUT THE ORIGIN)")
      text = "ГЛАВНЫЙ ВЕКТОР И ГЛАВНЫЙ МОМЕНТ СИЛ "// &
        "ИНЕРЦИИ, СИЛА И МОМЕНТ НА СТОЙКУ "// &
        "(МОМЕНТЫ ОТНОСИТЕЛЬНО НАЧАЛА КООРДИНАТ)"
    case ("MAX")
      text = "НАИБ"
    case ("MIN")
      text = "НАИМ"
    case ("STEPS LEFT OUT")
      text = "ПОЛОЖЕНИЙ ИСКЛ."
    case ("JAMMED OR LOST CONTACT: NO FORCES, NOT IN MAX, MIN, MEAN")
      text = "ЗАКЛИНИВАНИЕ ИЛИ ПОТЕРЯ КОНТАКТА: СИЛ НЕТ, НЕ В МАКС., МИН., СРЕДН."
    case ("MEAN")
      text = "СРЕДН"
    case ("AT ")
      text = "ПРИ "
    case ("WORK OF ")
      text = "РАБОТА "
    ! friction in the pairs of the generic engine (summary block and self-check)
    case ("WORK AND EFFICIENCY WITH FRICTION")
      text = "РАБОТА И КПД С УЧЕТОМ ТРЕНИЯ"
    case ("ETA = 1 - A_LOSS/A_DRIVER OVER A WHOLE TURN OF THE INPUT: THE CYCLE EFFICIENCY")
      text = "ETA = 1 - A_LOSS/A_DRIVER ЗА ПОЛНЫЙ ОБОРОТ ВХОДНОГО "// &
        "ЗВЕНА: ЦИКЛОВОЙ КПД"
    case ("ETA = 1 - A_LOSS/A_DRIVER OVER LESS THAN A WHOLE TURN: NOT THE CYCLE EFFICIENCY")
      text = "ETA = 1 - A_LOSS/A_DRIVER МЕНЕЕ ЧЕМ ЗА ОБОРОТ: НЕ "// &
        "ЦИКЛОВОЙ КПД"
    case ("(THE DRIVER'S WORK ALSO CHANGES THE KINETIC AND POTENTIAL ENERGY)")
      text = "(РАБОТА ДВИГАТЕЛЯ ИДЕТ ТАКЖЕ НА ИЗМЕНЕНИЕ "// &
        "КИНЕТИЧЕСКОЙ И ПОТЕНЦИАЛЬНОЙ ЭНЕРГИИ)"
    case ("ETA NOT DEFINED: THE DRIVER DELIVERS NO NET WORK OVER THE RUN")
      text = "КПД НЕ ОПРЕДЕЛЕН: РАБОТА ДВИГАТЕЛЯ ЗА РАСЧЕТ "// &
        "НЕ ПОЛОЖИТЕЛЬНА"
    case ("MAX EQUILIBRIUM RESIDUAL WITH FRICTION LOADS")
      text = "НАИБ. НЕВЯЗКА РАВНОВЕСИЯ С СИЛАМИ ТРЕНИЯ"
    case ("MAX M1 MISMATCH, POWER BALANCE WITH FRICTION")
      text = "НАИБ. РАСХОЖДЕНИЕ M1, БАЛАНС МОЩНОСТЕЙ С ТРЕНИЕМ"
    case ("MAX F_drive MISMATCH, POWER BALANCE WITH FRICTION")
      text = "НАИБ. РАСХОЖДЕНИЕ F_drive, БАЛАНС МОЩНОСТЕЙ С "// &
        "ТРЕНИЕМ"
    ! machine dynamics (the DYNAMICS block and its self-check line)
    case ("DYNAMICS (REDUCED TO THE INPUT LINK)")
      text = "ДИНАМИЧЕСКИЙ РАСЧЕТ (ПРИВЕДЕНИЕ К ВХОДНОМУ ЗВЕНУ)"
    case ("MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE WITH FRICTION")
      text = "НАИБ. РАСХОЖДЕНИЕ УСИЛИЙ ПРИВОДОВ С БАЛАНСОМ "// &
        "МОЩНОСТЕЙ С ТРЕНИЕМ"
    case ("MAX MISMATCH OF THE DRIVES' EFFORTS, POWER BALANCE")
      text = "НАИБ. РАСХОЖДЕНИЕ УСИЛИЙ ПРИВОДОВ С БАЛАНСОМ МОЩНОСТЕЙ"
    case ("MAX |M1 - M_d|/|M_d| WITH THE TRUE MOTION")
      text = "НАИБ. |M1 - M_d|/|M_d| ПРИ ИСТИННОМ ДВИЖЕНИИ"
    case ("M_d")
      text = "M_d (ДВИЖУЩИЙ МОМЕНТ)"
    case ("J_flywheel")
      text = "МАХОВИК J_flywheel"
    case ("flywheel_density")
      text = "МАХОВИК: ПЛОТНОСТЬ"
    case ("flywheel_width_ratio")
      text = "МАХОВИК: b/D"
    case ("flywheel_D")
      text = "МАХОВИК: ДИАМЕТР D"
    case ("flywheel_b")
      text = "МАХОВИК: ШИРИНА b"
    case ("flywheel_m")
      text = "МАХОВИК: МАССА m"
    case ("flywheel_note")
      text = "МАХОВИК"
    case ("a disc: J_flywheel = m D^2/8, m = density pi D^2 b/4, b = width_ratio D")
      text = "ДИСК: J_flywheel = m D^2/8, m = ПЛОТНОСТЬ pi D^2 b/4, b = (b/D) D"
    case ("no flywheel: J_flywheel = 0")
      text = "МАХОВИКА НЕТ: J_flywheel = 0"
    case ("none")
      text = "НЕТ"
    case ("kg/m^3")
      text = "кг/м^3"
    case ("J_flywheel_textbook")
      text = "МАХОВИК ПО МЕРЦАЛОВУ"
    case ("textbook_difference")
      text = "РАЗНИЦА С МЕРЦАЛОВЫМ"
    case ("J_rotor")
      text = "J_rotor (РОТОР)"
    case ("J_red_min")
      text = "ПРИВЕДЕННЫЙ МОМЕНТ ИНЕРЦИИ НАИМ"
    case ("J_red_max")
      text = "ПРИВЕДЕННЫЙ МОМЕНТ ИНЕРЦИИ НАИБ"
    case ("omega_mean")
      text = "omega СРЕДНЯЯ"
    case ("omega_max")
      text = "omega НАИБ"
    case ("phi_omega_max")
      text = "phi ПРИ omega НАИБ"
    case ("omega_min")
      text = "omega НАИМ"
    case ("phi_omega_min")
      text = "phi ПРИ omega НАИМ"
    case ("delta")
      text = "КОЭФФ. НЕРАВНОМЕРНОСТИ delta"
    case ("delta_asked")
      text = "delta ЗАДАННЫЙ"
    case ("period")
      text = "ПЕРИОД ЦИКЛА"
    case ("%")
      text = "%"
    case ("s")
      text = "с"
    ! units (ГОСТ symbols, as the 1991 printouts write them)
    case ("J")
      text = "Дж"
    case ("m")
      text = "м"
    case ("mm")
      text = "мм"
    case ("kg")
      text = "кг"
    case ("kg*m^2")
      text = "кг*м^2"
    case ("N")
      text = "Н"
    case ("N*m")
      text = "Н*м"
    case ("deg")
      text = "град"
    case ("rad/s")
      text = "рад/с"
    case ("rad/s^2")
      text = "рад/с^2"
    case ("m/s^2")
      text = "м/с^2"
    case ("m/rad")
      text = "м/рад"
    case ("m/rad^2")
      text = "м/рад^2"
    case ("1/rad")
      text = "1/рад"
    case ("steps")
      text = "положений"
    case ("satellites")
      text = "сателлитов"
    case ("rad")
      text = "рад"
    case ("m/s")
      text = "м/с"
    case ("W")
      text = "Вт"
    ! the words of the SVG sheets (the course's wording: план скоростей, план сил, рычаг Жуковского)
    case ("deck")
      text = "файл данных"
    case ("step")
      text = "положение"
    case ("stage")
      text = "ступень"
    case ("stages")
      text = "ступеней"
    case ("of")
      text = "из"
    case ("at")
      text = "под углом"
    case ("gravity down the sheet")
      text = "сила тяжести вниз по листу"
    case ("lengths")
      text = "длины"
    case ("forces")
      text = "силы"
    case ("pair force")
      text = "реакция"
    case ("load")
      text = "нагрузка"
    case ("weight")
      text = "вес"
    case ("inertia")
      text = "инерция"
    case ("Forces of the step (angles counterclockwise from the x axis of the mechanism's frame)")
      text = "Силы положения (углы против часовой "// &
        "стрелки от оси x системы координат "// &
        "механизма)"
    case ("Hodographs of the pair forces")
      text = "Годографы реакций в кинематических парах"
    case ("Tip of each force vector over the cycle, in the frame of the tables (x right, y up); point k = step k; "// &
      "O = zero force.")
      text = "Конец вектора каждой силы за цикл в системе координат "// &
        "таблиц (x вправо, y вверх); точка k = положение k; "// &
        "O = нулевая сила."
    case ("Pair forces of every stage as vectors")
      text = "Реакции каждой ступени как векторы"
    case ("The rows of this table are stages, not steps of a cycle: no hodographs and no diagrams against an "// &
      "input angle.")
      text = "Строки этой таблицы - ступени, а не положения цикла: "// &
        "ни годографов, ни диаграмм по углу входного звена."
    case ("This table has no pair force with an angle column: no hodographs.")
      text = "В таблице нет реакций со столбцом угла: годографов нет."
    case ("max")
      text = "наиб."
    case ("mean")
      text = "среднее"
    case ("Driving effort")
      text = "Движущее усилие"
    case ("This table has no driving moment or force column.")
      text = "В таблице нет столбца движущего момента или силы."
    case ("Driving force")
      text = "Движущая сила"
    case ("Driving moment")
      text = "Движущий момент"
    case ("against")
      text = "по"
    case ("Magnitudes of the pair forces against")
      text = "Модули реакций по"
    case ("No pair forces to show.")
      text = "Реакций для показа нет."
    case ("force")
      text = "сила"
    case ("no pair force")
      text = "нет реакций"
    case ("at every step")
      text = "во всех положениях"
    case ("Plan of velocities")
      text = "План скоростей"
    case ("Plan of accelerations")
      text = "План ускорений"
    case ("Zhukovsky's lever")
      text = "Рычаг Жуковского"
    case ("plan of velocities turned by 90 deg")
      text = "план скоростей, повернутый на 90 град"
    case ("Force polygons of the links")
      text = "Планы сил звеньев"
    case ("link")
      text = "звено"
    case ("Machine dynamics (reduced to the input link)")
      text = "Динамика машины (приведение к входному звену)"
    case ("Steady cycle")
      text = "Установившийся режим"
    case ("flywheel")
      text = "маховик"
    case ("textbook")
      text = "по учебнику"
    case ("Reduced moment of inertia J_red")
      text = "Приведенный момент инерции J_red"
    case ("Reduced moment M_red and M_d (dashed)")
      text = "Приведенный момент M_red и M_d (штрих)"
    case ("Change of kinetic energy dT")
      text = "Изменение кинетической энергии dT"
    case ("Speed omega1 (dashed: mean, max, min)")
      text = "Скорость omega1 (штрих: средн., наиб., наим.)"
    case ("Wittenbauer's curve: dT against J_red")
      text = "Кривая Виттенбауэра: dT по J_red"
    case ("Force polygons")
      text = "Планы сил"
    case ("balancing effort from the lever")
      text = "уравновешивающее усилие по рычагу"
    case ("analytic value of the step")
      text = "аналитическое значение в положении"
    case ("relative difference")
      text = "относительное расхождение"
    case ("flywheel and rotor included")
      text = "маховик и ротор учтены"
    case ("pair friction included")
      text = "трение в парах учтено"
    case ("not drawn")
      text = "не построен"
    case ("arrows: directions of the loads")
      text = "стрелки: направления нагрузок"
    case ("known forces first, then the pair forces")
      text = "сначала известные силы, затем реакции"
    case ("no driver column")
      text = "нет столбца движущего усилия"
    case ("the driving link is at rest")
      text = "ведущее звено неподвижно"
    case ("the driver is not a moment on a link of the drawing")
      text = "движущее усилие - не момент на звене чертежа"
    case ("the driver is neither a moment on a link nor a force on a slider of the drawing")
      text = "движущее усилие - ни момент на звене, ни сила на ползуне чертежа"
    case ("Force polygons of the groups")
      text = "Планы сил групп"
    case ("Assur group")
      text = "группа"
    case ("input link")
      text = "входное звено"
    case ("through the joint")
      text = "через шарнир"
    case ("the group apart")
      text = "группа отдельно"
    case ("known forces first, then the unknown reactions")
      text = "сначала известные силы, затем искомые реакции"
    case ("Mechanism")
      text = "Механизм"
    case ("position")
      text = "положение"
    case ("the plans in the mechanism's frame")
      text = "планы в системе координат чертежа механизма"
    case ("Loads on the lever")
      text = "Нагрузки на рычаге"
    case ("image")
      text = "точка плана"
    case ("arms on the lever")
      text = "плечи на рычаге"
    case ("Values read off the plans")
      text = "Величины по планам"
    case ("counterclockwise")
      text = "против часовой стрелки"
    case ("clockwise")
      text = "по часовой стрелке"
    case ("at the pole")
      text = "в полюсе"
    case ("not drawn, shorter than 1 mm")
      text = "не показаны, короче 1 мм"
    case ("Balancing effort")
      text = "Уравновешивающее усилие"
    case ("read off the sheet (vectors to 0.5 mm, arms to 1 mm)")
      text = "по чертежу (векторы с точностью 0,5 мм, плечи 1 мм)"
    case ("lever")
      text = "рычаг"
    case ("polygons")
      text = "планы сил"
    case ("relative velocities: v_PQ of a link's points, r along a guide")
      text = "относительные скорости: v_PQ точек звена, r вдоль направляющей"
    case ("components: n normal, τ tangential, k Coriolis, r relative")
      text = "составляющие: n норм., τ касат., k кориол., r относит."
    case ("Plans of velocities, accelerations, forces")
      text = "Планы скоростей, ускорений, сил"
    case ("Mechanism with its forces")
      text = "Механизм с силами"
    case ("Hodographs and diagrams")
      text = "Годографы и диаграммы"
    case ("not drawn, shorter than 1 mm at μF")
      text = "не показаны, короче 1 мм при μF"
    case ("under 1 mm, not drawn")
      text = "короче 1 мм, не показаны"
    case ("The input step")
      text = "Шаг входного звена"
    case ("is coarser than")
      text = "крупнее"
    case ("next to a load that switches on or off")
      text = "рядом с включением или "// &
        "выключением нагрузки"
    case ("the curves join the steps by chords and may miss the true peaks and the true mean; rerun with a "// &
      "finer step")
      text = "кривые соединяют положения хордами и могут "// &
        "пропустить истинные максимумы и истинное "// &
        "среднее; повторите расчет с меньшим шагом"
    case ("points drawn")
      text = "точек показано"
    case ("Shaking force and moment (the resultant of the inertia forces)")
      text = "Главный вектор и главный момент сил инерции"
    case ("Shaking moment")
      text = "Главный момент сил инерции"
    case default
      text = english
    end select
  end function label

  !> A unit symbol for a drawing in language `lang`: the table's symbol (Н*м, кг*м^2) with the
  !> typographic dot and superscript (Н·м, кг·м²); unknown units as they are.
  pure function unit_symbol(unit, lang) result(text)
    !> The unit as the tables write it ("N", "N*m", "deg").
    character(*), intent(in) :: unit
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = unit
    if (lang /= lang_ru) return
    text = replace_all(replace_all(label(unit, lang), "*", "·"), "^2", "²")
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
    !> The English name.
    character(*), intent(in) :: english
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = english
    if (lang /= lang_ru) return
    if (index(english, "STAGE ") == 1 .or. index(adjustl(english), "DYAD ") == 1 .or. &
      (index(english, "FORCE ") == 1 .or. index(english, "MOMENT ") == 1) .and. index(english, " LINK") > 0) then
      text = replace_all(text, "STAGE ", "СТУПЕНЬ ")
      text = replace_all(text, ": SPUR", ": ПРЯМОЗУБАЯ")
      text = replace_all(text, ": HELICAL", ": КОСОЗУБАЯ")
      text = replace_all(text, ": BEVEL", ": КОНИЧЕСКАЯ")
      text = replace_all(text, ": PLANETARY", ": ПЛАНЕТАРНАЯ")
      text = replace_all(text, "DYAD ", "ДИАДА ")
      text = replace_all(text, " ON LINKS ", " НА ЗВЕНЬЯХ ")
      text = replace_all(text, " LINKS ", " ЗВЕНЬЯ ")
      text = replace_all(text, " AND ", " И ")
      text = replace_all(text, ", MODE ", ", СБОРКА ")
      text = replace_all(text, "FORCE ", "СИЛА ")
      text = replace_all(text, "MOMENT ", "МОМЕНТ ")
      text = replace_all(text, " LINK", " ЗВЕНО")
    else if (is_linkage_echo(adjustl(english))) then
      text = linkage_echo_ru(english)
    else if (index(english, "M") == 1 .and. (index(english, " POWER") > 0 .or. index(english, " HOUSING") > 0 .or. &
      index(english, " BALANCE") > 0)) then
      ! a gear stage's torques: from the power balance, on the housing, from the torque balance
      text = replace_all(text, " POWER", " МОЩН.")
      text = replace_all(text, " HOUSING", " КОРПУСА")
      text = replace_all(text, " BALANCE", " БАЛАНС")
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
    text = replace_all(text, "STRUCTURAL ANALYSIS", "СТРУКТУРНЫЙ АНАЛИЗ")
    text = replace_all(text, "MOVING LINKS n", "ПОДВИЖНЫХ ЗВЕНЬЕВ n")
    text = replace_all(text, "LOWER PAIRS p5", "НИЗШИХ ПАР p5")
    text = replace_all(text, "HIGHER PAIRS p4", "ВЫСШИХ ПАР p4")
    text = replace_all(text, "NUMBER OF DRIVES", "ЧИСЛО НАЧАЛЬНЫХ ЗВЕНЬЕВ")
    text = replace_all(text, "STRUCTURE FORMULA:", "ФОРМУЛА СТРОЕНИЯ:")
    text = replace_all(text, "CLASS OF THE MECHANISM:", "КЛАСС МЕХАНИЗМА:")
    text = replace_all(text, "INPUT LINK(S) (MECHANISM OF CLASS I)", &
      "НАЧАЛЬНОЕ ЗВЕНО (МЕХАНИЗМ I КЛАССА)")
    ! a dyad's kind in the course's letters: В (вращательная) for R, П (поступательная) for P
    k = index(text, "), KIND ")
    if (k > 0) text = text(1:k + 7)//course_kind(text(k + 8:))
    text = replace_all(text, "DYAD (GROUP OF CLASS II, ORDER 2), KIND", &
      "ДИАДА (ГРУППА II КЛАССА 2-ГО ПОРЯДКА), ВИД")
    text = replace_all(text, "GROUP OF CLASS III, ORDER 3", &
      "ГРУППА III КЛАССА 3-ГО ПОРЯДКА")
    text = replace_all(text, "GROUP OF CLASS III, ORDER 4", &
      "ГРУППА III КЛАССА 4-ГО ПОРЯДКА")
    text = replace_all(text, "(TWO TERNARY BASE LINKS AND FOUR BINARY LINKS)", &
      "(ДВА БАЗОВЫХ ЗВЕНА С ТРЕМЯ ПАРАМИ)")
    text = replace_all(text, "(A TERNARY BASE LINK AND THREE BINARY LINKS)", &
      "(БАЗОВОЕ ЗВЕНО С ТРЕМЯ ПАРАМИ)")
    text = replace_all(text, "GROUP OF CLASS IV, ORDER 2", &
      "ГРУППА IV КЛАССА 2-ГО ПОРЯДКА")
    text = replace_all(text, "(A CLOSED FOUR-LINK CONTOUR)", &
      "(ЗАМКНУТЫЙ ЧЕТЫРЕХЗВЕННЫЙ КОНТУР)")
    text = replace_all(text, "(CLASS NOT DETERMINED)", "(КЛАСС НЕ ОПРЕДЕЛЕН)")
    text = replace_all(text, "GROUP OF ", "ГРУППА ИЗ ")
    text = replace_all(text, ", FOLLOWS THE LINK", ", ПОВОРАЧИВАЕТСЯ СО ЗВЕНОМ")
    text = replace_all(text, ", GUIDE ON ", ", НАПРАВЛЯЮЩАЯ НА ЗВЕНЕ ")
    text = replace_all(text, ", INPUT ", ", ВХОД ")
    text = replace_all(text, ", EFFORT ", ", УСИЛИЕ ")
    text = replace_all(text, "DRIVE ", "ПРИВОД ")
    text = replace_all(text, "PAIR ", "ПАРА ")
    text = replace_all(text, "FORCE ", "СИЛА ")
    text = replace_all(text, "MOMENT ", "МОМЕНТ ")
    text = replace_all(text, " LINKS (", " ЗВЕНЬЕВ (")
    text = replace_all(text, " LINKS ", " ЗВЕНЬЯ ")
    text = replace_all(text, " LINKS", " ЗВЕНЬЕВ")
    text = replace_all(text, " AND ", " И ")
    text = replace_all(text, "LINK ", "ЗВЕНО ")
  end function linkage_echo_ru

  !> A note in parentheses after a unit or a value, in Russian (unknown notes unchanged).
  pure function note(english) result(text)
    character(*), intent(in) :: english
    character(len=:), allocatable :: text
    select case (english)
    case ("frame 1")
      text = "система 1"
    case ("frame 2")
      text = "система 2"
    case ("rise; derived")
      text = "подъем; вычислено"
    case ("along +x2")
      text = "вдоль +x2"
    case ("from forces")
      text = "из сил"
    case ("power balance")
      text = "баланс мощностей"
    case ("carrier, from forces")
      text = "водило, из сил"
    case ("on the ring, from forces")
      text = "на коронном колесе, из сил"
    case ("echoed below as derived link coordinates")
      text = "ниже - пересчитанные координаты звеньев"
    case ("derived")
      text = "вычислено"
    case default
      text = english
    end select
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

end module kinetostat_labels
