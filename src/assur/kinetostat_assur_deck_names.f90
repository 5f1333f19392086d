!> `&assur` decks: the dyads' kinds by name in the deck text (`dyad(1)%kind = RRR`) and the
!> message that names an unknown kind.
module kinetostat_assur_deck_names
  use kinetostat_error, only: error_t
  use kinetostat_text, only: int_str, lower, upper
  use kinetostat_deck, only: deck_line_count, deck_line, deck_context_t, deck_source_t, comment_start
  use kinetostat_assur_kinematics, only: kind_names
  implicit none
  private
  public :: kind_names_as_codes, name_unknown_kind


contains


  !> The dyads' kinds by name, as the docs name them: `dyad(i)%kind = RRR` or `'RRR'` (any
  !> case; RRR RRP RPR PRP RPP) becomes the code 1..5, blank-padded to the same length (the
  !> columns of every message stay those of the deck). Other text is left as it is.
  pure subroutine kind_names_as_codes(deck_text)
    !> The deck (a copy), its records changed in place.
    type(deck_source_t), intent(inout) :: deck_text
    integer :: r, at, from, i, j, code, n
    character(len=:), allocatable :: low
    associate (records => deck_text%records)
      do r = 1, size(records)
        low = lower(records(r))
        from = 1
        do
          at = index(low(from:), "%kind")
          if (at == 0) exit
          i = from + at - 1 + len("%kind")
          from = i
          i = skip_blanks(low, i)
          if (i > len(low)) exit
          if (low(i:i) /= "=") cycle
          i = skip_blanks(low, i + 1)
          if (i + 2 > len(low)) exit
          j = i
          if (low(i:i) == "'" .or. low(i:i) == '"') j = i + 1
          if (j + 2 > len(low)) exit
          code = findloc(kind_names, upper(low(j:j + 2)), dim=1)
          if (code == 0) cycle
          n = j + 3 ! just after the name
          if (j > i) then
            if (n > len(low)) cycle
            if (low(n:n) /= low(i:i)) cycle ! the closing quote
            n = n + 1
          end if
          if (n <= len(low)) then
            if (index(" ,/!"//achar(9), low(n:n)) == 0) cycle ! a longer word
          end if
          records(r)(i:n - 1) = repeat(" ", n - i)
          records(r)(i:i) = achar(iachar("0") + code)
        end do
      end do
    end associate
  end subroutine kind_names_as_codes

  !> The first non-blank position of `text` at or after i (len + 1 when none).
  pure integer function skip_blanks(text, i) result(k)
    character(*), intent(in) :: text
    integer, intent(in) :: i
    k = i
    do while (k <= len(text))
      if (text(k:k) /= " " .and. text(k:k) /= achar(9)) exit
      k = k + 1
    end do
  end function skip_blanks

  !> A READ that failed on a line with a dyad's kind given as a name that is none of the
  !> kinds (`dyad(1)%kind = 'RRS'`): the message says so and lists the names, instead of
  !> "a number is expected" (names are accepted).
  pure subroutine name_unknown_kind(source, ctx, error)
    type(deck_source_t), intent(in) :: source
    type(deck_context_t), intent(in) :: ctx
    !> The READ's error ("deck.nml:11: &assur: ..."), replaced when its line has such a name.
    type(error_t), intent(inout) :: error
    character(len=:), allocatable :: text, low, designator, value
    integer :: line, d, ios, at, i, j, start
    if (index(error%message, ctx%path//":") /= 1) return
    d = len(ctx%path) + 2
    if (d > len(error%message)) return
    d = d - 1 + verify(error%message(d:), "0123456789")
    if (d <= len(ctx%path) + 2) return
    read (error%message(len(ctx%path) + 2:d - 1), *, iostat=ios) line
    if (ios /= 0 .or. line < 1 .or. line > deck_line_count(source)) return
    text = deck_line(source, line)
    ! the comment, if any, is not looked at
    low = lower(text(1:comment_start(text) - 1))
    start = 1
    do
      at = index(low(start:), "%kind")
      if (at == 0) return
      at = start + at - 1
      start = at + 5
      i = skip_blanks(low, at + 5)
      if (i > len(low)) return
      if (low(i:i) /= "=") cycle
      i = skip_blanks(low, i + 1)
      if (i > len(low)) return
      ! a text: quoted, or a word
      if (low(i:i) == "'" .or. low(i:i) == '"') then
        j = index(low(i + 1:), low(i:i))
        if (j == 0) return
        value = text(i + 1:i + j - 1)
        j = i + j
      else if (low(i:i) >= "a" .and. low(i:i) <= "z") then
        j = i
        do while (j < len(low))
          if (index(" ,/", low(j + 1:j + 1)) > 0) exit
          j = j + 1
        end do
        value = text(i:j)
      else
        cycle
      end if
      if (any(kind_names == upper(trim(adjustl(value))))) cycle
      ! the designator before %kind: dyad(k)
      j = max(j, i)
      d = at - 1
      do while (d >= 1)
        if (index("abcdefghijklmnopqrstuvwxyz0123456789_() ", low(d:d)) == 0) exit
        if (low(d:d) == " " .and. d < at - 1) then
          if (low(d + 1:d + 1) /= " " .and. low(d + 1:d + 1) /= "(") exit
        end if
        d = d - 1
      end do
      designator = trim(adjustl(text(d + 1:at + 4)))
      error%message = ctx%path//":"//int_str(line)//": &"//ctx%group//": "//designator//" = "// &
        trim(text(i:j))//": unknown kind '"//trim(adjustl(value))//"' (a dyad's kind is RRR, RRP, RPR, PRP or "// &
        "RPP, or its number 1 to 5)"
      return
    end do
  end subroutine name_unknown_kind

end module kinetostat_assur_deck_names
