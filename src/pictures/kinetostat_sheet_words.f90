!> The words of the SVG sheets in English and Russian. English is the key and the English
!> text; Russian follows the course's wording (план скоростей, план сил, рычаг Жуковского)
!> and the ГОСТ unit symbols (Н, Н·м, град). A phrase not in the list is returned as it is.
module kinetostat_sheet_words
  use kinetostat_labels, only: lang_ru
  implicit none
  private
  public :: word, unit_word

contains

  !> The phrase `english` in language `lang`.
  pure function word(english, lang) result(text)
    !> The English phrase (key).
    character(*), intent(in) :: english
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = english
    if (lang /= lang_ru) return
    select case (english)
    case ("deck")
      text = "файл данных"
    case ("step")
      text = "положение"
    case ("steps")
      text = "положений"
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
    case ("group")
      text = "группа"
    case ("input link")
      text = "входное звено"
    case ("known forces first, then the unknown reactions")
      text = "сначала известные силы, затем искомые реакции"
    case ("Plans of velocities, accelerations, forces")
      text = "Планы скоростей, ускорений, сил"
    case ("Mechanism with its forces")
      text = "Механизм с силами"
    case ("Hodographs and diagrams")
      text = "Годографы и диаграммы"
    case ("components")
      text = "составляющие"
    case ("normal")
      text = "норм."
    case ("tangential")
      text = "касат."
    case ("Coriolis")
      text = "кориол."
    case ("relative")
      text = "относит."
    case default
      text = english
    end select
  end function word

  !> A unit symbol in language `lang` (Н, Н·м, град, м, ...); unknown units as they are.
  pure function unit_word(unit, lang) result(text)
    !> The unit as the tables write it ("N", "N*m", "deg").
    character(*), intent(in) :: unit
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = unit
    if (lang /= lang_ru) return
    select case (unit)
    case ("N")
      text = "Н"
    case ("N*m")
      text = "Н·м"
    case ("deg")
      text = "град"
    case ("m")
      text = "м"
    case ("mm")
      text = "мм"
    case ("s")
      text = "с"
    case ("rad")
      text = "рад"
    case ("rad/s")
      text = "рад/с"
    case ("rad/s^2")
      text = "рад/с²"
    case ("m/s")
      text = "м/с"
    case ("m/s^2")
      text = "м/с²"
    case ("kg")
      text = "кг"
    case ("kg*m^2")
      text = "кг·м²"
    case ("W")
      text = "Вт"
    case ("J")
      text = "Дж"
    case default
      text = unit
    end select
  end function unit_word

end module kinetostat_sheet_words
