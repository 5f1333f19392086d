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
      text = "САМОПРОВЕРКА (относительная; допуск "
    case ("MAX EQUILIBRIUM RESIDUAL, ALL LINKS AND STEPS")
      text = "НАИБ. НЕВЯЗКА РАВНОВЕСИЯ, ВСЕ ЗВЕНЬЯ И ШАГИ"
    case ("MISMATCH VS POWER BALANCE")
      text = "РАСХОЖДЕНИЕ С БАЛАНСОМ МОЩНОСТЕЙ"
    case ("MAX ")
      text = "НАИБ. "
    case default
      text = english
    end select
  end function label

end module kinetostat_labels
