!> Languages of the legacy table and the labels shared by every mechanism's table.
!> English is the program's own wording; Russian follows the 1991 printouts
!> (ИСХОДНЫЕ ДАННЫЕ, РЕЗУЛЬТАТЫ РАСЧЕТА, ...). Mechanism-specific headings live in each
!> mechanism's layout module.
module kinetostat_labels
  implicit none
  private
  public :: lang_en, lang_ru, lang_from_name, label

  !> Language: English (default).
  integer, parameter :: lang_en = 1
  !> Language: Russian (UTF-8).
  integer, parameter :: lang_ru = 2

contains

  !> Language code from its name ("en", "ru"); 0 when unknown.
  pure integer function lang_from_name(name)
    !> Name given with --lang.
    character(*), intent(in) :: name
    select case (name)
    case ("en")
      lang_from_name = lang_en
    case ("ru")
      lang_from_name = lang_ru
    case default
      lang_from_name = 0
    end select
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
    case ("SHAKING FORCE AND MOMENT, FORCE AND MOMENT ON THE FRAME (MOMENTS ABOUT THE ORIGIN)")
      text = "ГЛАВНЫЙ ВЕКТОР И ГЛАВНЫЙ МОМЕНТ СИЛ "// &
        "ИНЕРЦИИ, СИЛА И МОМЕНТ НА СТОЙКУ "// &
        "(МОМЕНТЫ ОТНОСИТЕЛЬНО НАЧАЛА КООРДИНАТ)"
    case ("MAX")
      text = "НАИБ"
    case ("MIN")
      text = "НАИМ"
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
    case ("MAX |M1 - M_d|/|M_d| WITH THE TRUE MOTION")
      text = "НАИБ. |M1 - M_d|/|M_d| ПРИ ИСТИННОМ ДВИЖЕНИИ"
    case ("M_d")
      text = "M_d (ДВИЖУЩИЙ МОМЕНТ)"
    case ("J_flywheel")
      text = "МАХОВИК J_flywheel"
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
    case ("steps")
      text = "положений"
    case default
      text = english
    end select
  end function label

end module kinetostat_labels
