!> The encoding of a deck: decks are read as UTF-8. A deck that is not valid UTF-8 but whose
!> every byte beyond ASCII is a Cyrillic letter of CP1251 (Windows-1251, what Notepad saves
!> as "ANSI" on a Russian Windows: 0xC0-0xFF А..я, 0xA8 Ё, 0xB8 ё) is decoded to UTF-8 as a
!> whole before it is read; anything else that is not UTF-8 is refused, naming the first
!> byte at fault and its line. docs/cli.md, "Strings in outputs".
module kinetostat_deck_encoding
  use kinetostat_text, only: utf8_length, int_str
  implicit none
  private
  public :: deck_as_utf8, utf8_problem

contains

  !> The deck's text as UTF-8: kept when it is valid UTF-8, decoded when it is CP1251 as
  !> above; otherwise `problem` says why (with the line), and `text` is left as it was.
  pure subroutine deck_as_utf8(text, problem)
    !> The deck's bytes; on return its UTF-8 text.
    character(len=:), allocatable, intent(inout) :: text
    !> Empty when the deck reads; else "LINE: reason" (the reason without the deck's name).
    character(len=:), allocatable, intent(out) :: problem
    integer :: i, n, first_bad, first_foreign, first_other, extra, at, c
    problem = ""
    ! the first byte that is not part of valid UTF-8, and the first such byte that is no
    ! CP1251 letter either
    first_bad = 0
    first_foreign = 0
    i = 1
    do while (i <= len(text))
      if (iachar(text(i:i)) < 128) then
        i = i + 1
        cycle
      end if
      n = utf8_length(text, i)
      if (n > 1) then
        i = i + n
        cycle
      end if
      if (first_bad == 0) first_bad = i
      if (.not. cp1251_letter(iachar(text(i:i)))) then
        first_foreign = i
        exit
      end if
      i = i + 1
    end do
    if (first_bad == 0) return
    if (first_foreign > 0) then
      problem = int_str(line_of(first_foreign))//": byte \x"//hex(iachar(text(first_foreign:first_foreign)))// &
        " is neither UTF-8 nor a Cyrillic letter of CP1251 (save the deck as UTF-8)"
      return
    end if
    ! not UTF-8, and every byte that is not is a CP1251 letter: CP1251 when all of the
    ! others beyond ASCII are letters too (else the rest is UTF-8 text: two encodings)
    first_other = 0
    do i = 1, len(text)
      if (iachar(text(i:i)) >= 128) then
        if (.not. cp1251_letter(iachar(text(i:i)))) then
          first_other = i
          exit
        end if
      end if
    end do
    if (first_other > 0) then
      problem = int_str(line_of(first_bad))//": byte \x"//hex(iachar(text(first_bad:first_bad)))// &
        " is not UTF-8, but line "//int_str(line_of(first_other))//" is UTF-8: the deck mixes two encodings "// &
        "(save it as UTF-8)"
      return
    end if
    ! decode: each letter becomes its two UTF-8 bytes
    extra = 0
    do i = 1, len(text)
      if (iachar(text(i:i)) >= 128) extra = extra + 1
    end do
    block
      character(len=:), allocatable :: utf8
      allocate (character(len=len(text) + extra) :: utf8)
      at = 0
      do i = 1, len(text)
        c = iachar(text(i:i))
        if (c < 128) then
          at = at + 1
          utf8(at:at) = text(i:i)
        else
          utf8(at + 1:at + 2) = cp1251_as_utf8(c)
          at = at + 2
        end if
      end do
      call move_alloc(utf8, text)
    end block
  contains
    !> The line of byte k (1 + the line feeds before it).
    pure integer function line_of(k)
      integer, intent(in) :: k
      integer :: j
      line_of = 1
      do j = 1, k - 1
        if (text(j:j) == achar(10)) line_of = line_of + 1
      end do
    end function line_of
  end subroutine deck_as_utf8

  !> Why `text` (a --set value, a line) is not valid UTF-8: "" when it is, else the first
  !> byte that is not ("byte \xFF is not UTF-8").
  pure function utf8_problem(text) result(problem)
    !> Any bytes.
    character(*), intent(in) :: text
    character(len=:), allocatable :: problem
    integer :: i, n
    problem = ""
    i = 1
    do while (i <= len(text))
      n = utf8_length(text, i)
      if (n == 0) then
        problem = "byte \x"//hex(iachar(text(i:i)))//" is not UTF-8"
        return
      end if
      i = i + n
    end do
  end function utf8_problem

  !> Whether byte c is a Cyrillic letter in CP1251 (А..я, Ё, ё).
  pure logical function cp1251_letter(c)
    integer, intent(in) :: c
    cp1251_letter = c >= 192 .or. c == 168 .or. c == 184
  end function cp1251_letter

  !> The UTF-8 bytes of CP1251 letter c (192..255: U+0410..U+044F; 168: Ё U+0401; 184: ё U+0451).
  pure function cp1251_as_utf8(c) result(u)
    integer, intent(in) :: c
    character(len=2) :: u
    integer :: code
    if (c == 168) then
      code = 1025
    else if (c == 184) then
      code = 1105
    else
      code = 1040 + (c - 192)
    end if
    u = achar(192 + code / 64)//achar(128 + mod(code, 64))
  end function cp1251_as_utf8

  !> A byte as two upper-case hex digits.
  pure function hex(c) result(t)
    integer, intent(in) :: c
    character(len=2) :: t
    character(len=*), parameter :: digits = "0123456789ABCDEF"
    t = digits(c / 16 + 1:c / 16 + 1)//digits(mod(c, 16) + 1:mod(c, 16) + 1)
  end function hex

end module kinetostat_deck_encoding
