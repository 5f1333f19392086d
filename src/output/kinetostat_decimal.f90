!> Exact binary-to-decimal conversion for the output policy (kinetostat_format): the edit
!> descriptors Fw.d, Ew.d[Ee] and ESw.d[Ee] of a real(wp), byte for byte as the compiler's
!> formatted WRITE prints them (default rounding: the exact binary value rounded to the
!> nearest decimal, ties to even), without the run-time library's cost.
!>
!> Fast path: x = m * 2**e (m < 2**53) times 10**s is rounded in exact 128-bit integer
!> arithmetic (x * 10**s = m * 5**s * 2**(e + s) for s >= 0, a long division for s < 0),
!> so the digits and the tie decision are exact, not estimated. Values whose scaled
!> product does not fit in 128 bits (|x| far from 1 for the digits asked) and descriptors
!> outside the fast path fall back to an internal WRITE with the same descriptor, so the
!> result is always the compiler's.
!> Every field routine writes into a character(*) dummy whose length IS the field width (as
!> an internal WRITE does), so intent(out)/(inout) with an assumed length is the design here.
! allow(assumed-size-character-intent)
module kinetostat_decimal
  use, intrinsic :: iso_fortran_env, only: int16, int64
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: edit_f, edit_exponent, put_es_compact, put_whole, i16
  public :: put_cell_number, put_cell_numbers

  !> Integer kind of the exact products (128 bits).
  integer, parameter :: i16 = selected_int_kind(38)
  !> Index of the implied DO loops of the tables below.
  integer, private :: i_
  !> Largest s of the table of 5**s (m * 5**31 < 2**53 * 2**72 fits the 128-bit products).
  integer, parameter :: max_pow5 = 31
  !> 5**s, s = 0..max_pow5.
  integer(i16), parameter :: pow5(0:max_pow5) = [(5_i16**i_, i_ = 0, max_pow5)]
  !> Largest t of the table of 10**t in 128 bits.
  integer, parameter :: max_pow10 = 38
  !> 10**t, t = 0..max_pow10.
  integer(i16), parameter :: pow10(0:max_pow10) = [(10_i16**i_, i_ = 0, max_pow10)]
  !> log10(2), for the first estimate of the decimal exponent.
  real(wp), parameter :: log10_2 = 0.30102999566398119521373889472449302677_wp
  !> "00", "01", ..., "99": two digits at a time.
  character(len=200), parameter :: digit_pairs = &
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839" // &
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879" // &
    "8081828384858687888990919293949596979899"
  !> Largest number of significant digits of the fast path (q < 10**18 fits in int64).
  integer, parameter :: max_digits = 17
  !> Width of the scratch texts.
  integer, parameter :: scratch_len = 72
  !> Digits after the point of a CSV cell or JSON number (ES20.12E3): cell_digits_fast's case.
  integer, parameter :: cell_decimals = 12
  !> 10**t as doubles, t = 0..max_exact_pow10 (exact: 5**22 < 2**53).
  integer, parameter :: max_exact_pow10 = 22
  !> The exact powers of ten as doubles.
  real(wp), parameter :: exact_pow10(0:max_exact_pow10) = [(real(pow10(i_), wp), i_ = 0, max_exact_pow10)]
  !> How far from a half the fraction of |x| * 10**s, computed in double precision, must lie
  !> for its rounding to be the exact one (its error is below 2**-10 where it is < 10**13).
  real(wp), parameter :: tie_margin = 2.0_wp**(-8)
  !> The exponent part of a CSV cell whose decimal exponent is i (cell_digits_fast's range).
  character(len=5), parameter :: exponent_texts(-12:12) = ["E-012", "E-011", "E-010", "E-009", "E-008", &
    "E-007", "E-006", "E-005", "E-004", "E-003", "E-002", "E-001", "E+000", "E+001", "E+002", "E+003", &
    "E+004", "E+005", "E+006", "E+007", "E+008", "E+009", "E+010", "E+011", "E+012"]
  !> A whole-number cell (flag, count) is written as one below this magnitude.
  real(wp), parameter :: whole_limit = 1.0e15_wp
  ! (The tables below are expressions of their index alone: an element of another named
  ! array in a long implied DO makes the compiler's evaluation quadratic, minutes a build.)
  !> The decimal exponent put_cell_numbers assumes for row j of its tables, in the table's
  !> first half (j = b, the biased binary exponent of |x|) floor(log10(2**(b - 1023))), the
  !> exponent of the binade's first double; in its second half (j = b + 2048) one more, for
  !> the part of the binade from the next power of ten on.
  !> 10**(12 - k) for the exponent k of row j, 0 outside the fast range (|x| times it is then
  !> 0 and the cell goes the exact way).
  real(wp), parameter :: cell_scales(0:4095) = [(merge(10.0_wp**min(max(cell_decimals &
    - (shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11)), 0), max_exact_pow10), 0.0_wp, &
    shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11) >= cell_decimals - max_exact_pow10 .and. &
    shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11) <= cell_decimals), i_ = 0, 4095)]
  !> The five bytes "E+ddd" of the exponent k of row j, little-endian in one integer (the
  !> separator is added in the bytes above them; |k| < 1000: k * 5243 / 2**19 is k / 100,
  !> k * 205 / 2**11 is k / 10).
  integer(int64), parameter :: cell_exponent_words(0:4095) = [(69_int64 + 256_int64 * merge(45_int64, 43_int64, &
    shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11) < 0) &
    + 65536_int64 * (48 + shiftr(abs(shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11)) * 5243, 19)) &
    + 16777216_int64 * (48 + mod(shiftr(abs(shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11)) * 205, 11), 10)) &
    + 4294967296_int64 * (48 + mod(abs(shifta((iand(i_, 2047) - 1023) * 78913, 18) + shiftr(i_, 11)), 10)), &
    i_ = 0, 4095)]
  !> The 4 decimal digits of n = 0..9999 as ASCII bytes of one integer, the first digit in
  !> its lowest byte (stored in this order on a little-endian machine). Each division is
  !> exact (n less its remainder), as a constant expression must be under -Werror.
  integer, parameter :: digit_quads(0:9999) = [(48 + (i_ - mod(i_, 1000)) / 1000 &
    + 256 * (48 + mod((i_ - mod(i_, 100)) / 100, 10)) &
    + 65536 * (48 + mod((i_ - mod(i_, 10)) / 10, 10)) + 16777216 * (48 + mod(i_, 10)), i_ = 0, 9999)]
  !> 12 - k for the exponent k of row j of the tables above (the power of ten of its scale).
  integer, parameter :: cell_scale_exponents(0:4095) = [(cell_decimals - (shifta((iand(i_, 2047) - 1023) * 78913, 18) &
    + shiftr(i_, 11)), i_ = 0, 4095)]
  !> Status of a field body: written.
  integer, parameter :: body_ok = 0
  !> Status of a field body: does not fit its width (the field is all '*').
  integer, parameter :: body_stars = 1
  !> Status of a field body: outside the fast path (the compiler's WRITE makes it).
  integer, parameter :: body_fallback = 2

contains

  !> Sign bit, mantissa and binary exponent of a finite x: |x| = m * 2**e.
  pure subroutine split(x, negative, m, e)
    real(wp), intent(in) :: x
    logical, intent(out) :: negative
    integer(int64), intent(out) :: m
    integer, intent(out) :: e
    integer(int64) :: bits
    integer :: biased
    bits = transfer(x, bits)
    negative = bits < 0
    biased = int(iand(shiftr(bits, 52), 2047_int64))
    m = iand(bits, shiftl(1_int64, 52) - 1_int64)
    if (biased == 0) then
      e = -1074
    else
      m = m + shiftl(1_int64, 52)
      e = biased - 1075
    end if
  end subroutine split

  !> q = m * 2**e * 10**s rounded to the nearest integer, ties to even, exactly; ok is false
  !> when the operands do not fit the 128-bit fast path (the caller then falls back).
  pure subroutine scaled_round(m, e, s, q, ok)
    integer(int64), intent(in) :: m
    integer, intent(in) :: e, s
    integer(i16), intent(out) :: q
    logical, intent(out) :: ok
    integer(i16) :: p, rem, half, num, den
    integer :: sh, bits_p
    ok = .false.
    q = 0
    if (s >= 0) then
      if (s > max_pow5) return
      p = int(m, i16) * pow5(s)
      sh = e + s
      bits_p = bit_length(p)
      if (sh >= 0) then
        if (bits_p + sh > 126) return
        q = shiftl(p, sh)
      else
        sh = -sh
        if (sh > 125) then
          ok = bits_p + 1 < sh ! then x * 10**s < 1/2: q = 0
          return
        end if
        q = shiftr(p, sh)
        rem = p - shiftl(q, sh)
        half = shiftl(1_i16, sh - 1)
        if (rem > half .or. (rem == half .and. btest(q, 0))) q = q + 1
      end if
    else
      if (-s > max_pow10) return
      if (e >= 0) then
        if (bit_length(int(m, i16)) + e > 126) return
        num = shiftl(int(m, i16), e)
        den = pow10(-s)
      else
        num = int(m, i16)
        if (bit_length(pow10(-s)) - e > 125) return
        den = shiftl(pow10(-s), -e)
      end if
      q = num / den
      rem = num - q * den
      if (2 * rem > den .or. (2 * rem == den .and. btest(q, 0))) q = q + 1
    end if
    ok = .true.
  end subroutine scaled_round

  !> Number of bits of a non-negative integer (0 for 0).
  pure integer function bit_length(p)
    integer(i16), intent(in) :: p
    bit_length = int(bit_size(p)) - leadz(p)
  end function bit_length

  !> |x| (finite, nonzero) rounded to n significant digits: q with 10**(n-1) <= q < 10**n
  !> and the decimal exponent k of the first digit (|x| ~ q * 10**(k - n + 1)).
  pure subroutine round_significant(m, e, n, q, k, ok)
    integer(int64), intent(in) :: m
    integer, intent(in) :: e, n
    integer(int64), intent(out) :: q
    integer, intent(out) :: k
    logical, intent(out) :: ok
    integer(i16) :: q16
    integer :: attempt, top
    q = 0
    top = e + int(bit_size(m)) - 1 - leadz(m)   ! 2**top <= |x| < 2**(top + 1)
    k = floor(top * log10_2)               ! exact: top * log10(2) is never near an integer
    do attempt = 1, 3
      call scaled_round(m, e, n - 1 - k, q16, ok)
      if (.not. ok) return
      if (q16 < pow10(n)) then
        q = int(q16, int64)
        return
      end if
      k = k + 1                            ! |x| >= 10**(k+1), or it rounded up to it
    end do
    ok = .false.
  end subroutine round_significant

  !> The n decimal digits of q (leading zeros kept) into text(1:n): eight digits at a time
  !> from the right (one 64-bit division, then two independent four-digit halves in 32-bit
  !> arithmetic), the rest two at a time.
  pure subroutine put_digits(q, n, text)
    integer(int64), intent(in) :: q
    integer, intent(in) :: n
    character(*), intent(inout) :: text
    integer(int64) :: r
    integer :: p, eight, high, low, rest, two
    r = q
    p = n
    do while (p >= 8)
      eight = int(mod(r, 100000000_int64))
      r = r / 100000000_int64
      high = eight / 10000
      low = eight - 10000 * high
      call put_pair(text(p - 7:p - 6), high / 100)
      call put_pair(text(p - 5:p - 4), mod(high, 100))
      call put_pair(text(p - 3:p - 2), low / 100)
      call put_pair(text(p - 1:p), mod(low, 100))
      p = p - 8
    end do
    rest = int(r)
    do while (p >= 2)
      two = mod(rest, 100)
      rest = rest / 100
      call put_pair(text(p - 1:p), two)
      p = p - 2
    end do
    if (p == 1) text(1:1) = achar(48 + mod(rest, 10))
  end subroutine put_digits

  !> The two digits of 0 <= two <= 99 into `pair`.
  pure subroutine put_pair(pair, two)
    character(len=2), intent(out) :: pair
    integer, intent(in) :: two
    pair = digit_pairs(2 * two + 1:2 * two + 2)
  end subroutine put_pair

  !> Number of decimal digits of q >= 0 (1 for 0).
  pure integer function digit_count(q)
    integer(int64), intent(in) :: q
    digit_count = 1
    do while (digit_count < 19)
      if (q < int(pow10(digit_count), int64)) return
      digit_count = digit_count + 1
    end do
  end function digit_count

  !> The exponent part of an E or ES field: "E+dd" (e = 0, |k| <= 99), "+ddd" (e = 0, |k| <= 999),
  !> "E+" followed by e digits; ok false when k does not fit.
  pure subroutine exponent_part(k, e, text, length, ok)
    integer, intent(in) :: k, e
    character(len=8), intent(out) :: text
    integer, intent(out) :: length
    logical, intent(out) :: ok
    character :: sign
    integer :: digits
    sign = "+"
    if (k < 0) sign = "-"
    ok = .true.
    if (e == 0) then
      if (abs(k) <= 99) then
        text(1:2) = "E"//sign
        call put_digits(int(abs(k), int64), 2, text(3:4))
        length = 4
      else if (abs(k) <= 999) then
        text(1:1) = sign
        call put_digits(int(abs(k), int64), 3, text(2:4))
        length = 4
      else
        ok = .false.
        length = 0
      end if
    else
      digits = e
      if (digits > 6 .or. abs(k) >= int(pow10(min(digits, 6)))) then
        ok = .false.
        length = 0
        return
      end if
      text(1:2) = "E"//sign
      call put_digits(int(abs(k), int64), digits, text(3:2 + digits))
      length = 2 + digits
    end if
  end subroutine exponent_part

  !> text = x written with ESw.d (scientific) or Ew.d (0.ddd form), or with ESw.dEe / Ew.dEe
  !> when e > 0, right-justified in len(text) = w.
  pure subroutine edit_exponent(x, d, e, scientific, text)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Digits after the point.
    integer, intent(in) :: d
    !> Exponent digits (0: the default form).
    integer, intent(in) :: e
    !> ES form (one digit before the point) rather than E (0.ddd).
    logical, intent(in) :: scientific
    !> The field (its length is the width w).
    character(*), intent(out) :: text
    character(len=scratch_len) :: body
    integer :: n, status, w
    w = len(text)
    call exponent_body(x, d, e, scientific, w, body, n, status)
    select case (status)
    case (body_ok)
      call right_justify(body(1:n), text)
    case (body_stars)
      text = repeat("*", w)
    case default
      call fallback_exponent(x, d, e, scientific, text)
    end select
  end subroutine edit_exponent

  !> The characters of an E or ES field without the blanks in front: body(1:n), status
  !> body_ok; body_stars when it does not fit in w; body_fallback outside the fast path.
  pure subroutine exponent_body(x, d, e, scientific, w, body, n, status)
    real(wp), intent(in) :: x
    integer, intent(in) :: d, e
    logical, intent(in) :: scientific
    !> Field width (decides the optional leading zero of the E form, and '*').
    integer, intent(in) :: w
    character(len=scratch_len), intent(out) :: body
    integer, intent(out) :: n, status
    character(len=8) :: expo
    integer(int64) :: m, q
    integer :: ex, digits, k, elen
    logical :: negative, ok
    n = 0
    status = body_fallback
    call split(x, negative, m, ex)
    digits = d
    if (scientific) digits = d + 1
    if (digits < 1 .or. digits > max_digits .or. w > scratch_len - 8) return
    if (m == 0) then
      q = 0
      k = 0
      if (.not. scientific) k = -1
    else
      call round_significant(m, ex, digits, q, k, ok)
      if (.not. ok) return
    end if
    if (.not. scientific) k = k + 1        ! 0.ddd form: the exponent of the digit before the first
    call exponent_part(k, e, expo, elen, ok)
    status = body_stars
    if (.not. ok) return
    if (negative) then
      n = 1
      body(1:1) = "-"
    end if
    if (scientific) then
      call put_digits(q, digits, body(n + 2:n + digits + 1))
      body(n + 1:n + 1) = body(n + 2:n + 2)
      body(n + 2:n + 2) = "."
      n = n + digits + 1
    else
      if (n + 2 + digits + elen <= w) then  ! the leading zero is optional: kept when it fits
        body(n + 1:n + 1) = "0"
        n = n + 1
      end if
      body(n + 1:n + 1) = "."
      call put_digits(q, digits, body(n + 2:n + digits + 1))
      n = n + digits + 1
    end if
    body(n + 1:n + elen) = expo(1:elen)
    n = n + elen
    if (n <= w) status = body_ok
  end subroutine exponent_body

  !> text = blanks, then s at its right end (len(s) <= len(text)).
  pure subroutine right_justify(s, text)
    character(*), intent(in) :: s
    character(*), intent(out) :: text
    integer :: w
    w = len(text)
    text(1:w - len(s)) = ""
    text(w - len(s) + 1:w) = s
  end subroutine right_justify

  !> The compiler's own E/ES edit (values or descriptors outside the fast path).
  pure subroutine fallback_exponent(x, d, e, scientific, text)
    real(wp), intent(in) :: x
    integer, intent(in) :: d, e
    logical, intent(in) :: scientific
    character(*), intent(out) :: text
    character(len=32) :: fmt
    character(len=2) :: letters
    letters = "e "
    if (scientific) letters = "es"
    if (e > 0) then
      write (fmt, '("(",a,i0,".",i0,"e",i0,")")') trim(letters), len(text), d, e
    else
      write (fmt, '("(",a,i0,".",i0,")")') trim(letters), len(text), d
    end if
    write (text, fmt) x
  end subroutine fallback_exponent

  !> text = x written with Fw.d, right-justified in len(text) = w. With `fits`: written only
  !> when the field leaves at least one blank in front, as `fits` says; otherwise nothing is
  !> written and `fits` is false (the caller chooses another form).
  pure subroutine edit_f(x, d, text, fits)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Digits after the point.
    integer, intent(in) :: d
    !> The field (its length is the width w).
    character(*), intent(out) :: text
    !> Whether the fixed form was written with a blank in front (asked for when present).
    logical, intent(out), optional :: fits
    character(len=scratch_len) :: body, wide
    integer :: n, status, first
    logical :: done
    if (present(fits)) then
      call fixed_fits(x, d, text, fits, done)
      if (done) return
      call fixed_body(x, d, scratch_len, body, n, status)
      if (status == body_fallback) then
        call write_f(x, d, wide)
        first = verify(wide, " ")
        n = scratch_len - first + 1
        body(1:n) = wide(first:)
      end if
      fits = n < len(text) .and. status /= body_stars
      if (fits) call right_justify(body(1:n), text)
      return
    end if
    call fixed_body(x, d, len(text), body, n, status)
    select case (status)
    case (body_ok)
      call right_justify(body(1:n), text)
    case (body_stars)
      text = repeat("*", len(text))
    case default
      call write_f(x, d, text)
    end select
  end subroutine edit_f

  !> edit_f's form with `fits` in one pass where |x| * 10**d rounds below 2**63 (every
  !> table field): the digits go straight into `text` from its right end (`done`); outside
  !> that range `done` is false and nothing is written. Up to 4 decimals (every table field)
  !> the product m * 5**d fits 64 bits and is rounded there; no division by a variable.
  pure subroutine fixed_fits(x, d, text, fits, done)
    real(wp), intent(in) :: x
    integer, intent(in) :: d
    character(*), intent(inout) :: text
    logical, intent(out) :: fits, done
    !> Decimals whose m * 5**d fits 64 bits (5**4 < 2**10).
    integer, parameter :: short_decimals = 4
    integer(int64) :: m, q, p, rem, half
    integer(i16) :: q16
    integer :: ex, n, nd, at, w, sh, i
    logical :: negative, ok
    done = .false.
    fits = .false.
    if (d < 0 .or. d > 18) return
    call split(x, negative, m, ex)
    sh = ex + d
    if (d <= short_decimals .and. sh < 0 .and. sh > -63) then
      p = m * int(pow5(d), int64)
      q = shiftr(p, -sh)
      rem = p - shiftl(q, -sh)
      half = shiftl(1_int64, -sh - 1)
      if (rem > half .or. (rem == half .and. btest(q, 0))) q = q + 1
    else
      call scaled_round(m, ex, d, q16, ok)
      if (.not. ok .or. q16 > int(huge(1_int64), i16)) return
      q = int(q16, int64)
    end if
    done = .true.
    ! the digits of q, at least d + 1 of them (the leading zero of |x| < 1: there is room)
    nd = max(digit_count(q), d + 1)
    n = nd + 1
    if (negative) n = n + 1
    w = len(text)
    fits = n < w
    if (.not. fits) return
    ! from the right end, a character at a time (no library call for a few bytes)
    at = w
    do i = 1, nd
      if (i == d + 1) then
        text(at:at) = "."
        at = at - 1
      end if
      text(at:at) = achar(48 + int(mod(q, 10_int64)))
      q = q / 10_int64
      at = at - 1
    end do
    if (negative) then
      text(at:at) = "-"
      at = at - 1
    end if
    do i = 1, at
      text(i:i) = " "
    end do
  end subroutine fixed_fits

  !> text = x written by the compiler's WRITE with Fw.d, w = len(text) (outside the fast path).
  pure subroutine write_f(x, d, text)
    real(wp), intent(in) :: x
    integer, intent(in) :: d
    character(*), intent(out) :: text
    character(len=32) :: fmt
    write (fmt, '("(f",i0,".",i0,")")') len(text), d
    write (text, fmt) x
  end subroutine write_f

  !> The characters of an Fw.d field without the blanks in front: body(1:n), with status
  !> as exponent_body's.
  pure subroutine fixed_body(x, d, w, body, n, status)
    real(wp), intent(in) :: x
    integer, intent(in) :: d
    !> Field width (decides the optional leading zero, and '*').
    integer, intent(in) :: w
    character(len=scratch_len), intent(out) :: body
    integer, intent(out) :: n, status
    integer(int64) :: m, int_part, frac_part
    integer(i16) :: q
    integer :: ex, ni
    logical :: negative, ok
    n = 0
    status = body_fallback
    call split(x, negative, m, ex)
    if (d < 0 .or. d > 18) return
    call scaled_round(m, ex, d, q, ok)
    if (.not. ok) return
    if (q >= pow10(18 + d)) return        ! integer part of 19 digits or more
    if (q <= int(huge(1_int64), i16)) then
      ! (64-bit division: the common case, several times faster than the 128-bit one)
      int_part = int(q, int64) / int(pow10(d), int64)
      frac_part = int(q, int64) - int_part * int(pow10(d), int64)
    else
      int_part = int(q / pow10(d), int64)
      frac_part = int(q - int(int_part, i16) * pow10(d), int64)
    end if
    if (negative) then
      n = 1
      body(1:1) = "-"
    end if
    ni = digit_count(int_part)
    ! the leading zero of |x| < 1 is optional: dropped only when the field is too narrow
    if (int_part == 0 .and. n + 2 + d > w .and. d > 0) ni = 0
    if (ni > 0) call put_digits(int_part, ni, body(n + 1:n + ni))
    n = n + ni
    body(n + 1:n + 1) = "."
    n = n + 1
    if (d > 0) call put_digits(frac_part, d, body(n + 1:n + d))
    n = n + d
    status = body_stars
    if (n <= w) status = body_ok
  end subroutine fixed_body

  !> Append x in ESw.dEe form without leading blanks to buf at pos+1.. (pos advanced):
  !> the text of adjustl(ES(d+e+6).dEe) for a CSV cell or a JSON number. The three-digit
  !> exponent form of every CSV cell and JSON number (e = 3) is written straight into buf
  !> (significant_digits); anything else goes through exponent_body.
  pure subroutine put_es_compact(x, d, e, buf, pos)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Digits after the point.
    integer, intent(in) :: d
    !> Exponent digits.
    integer, intent(in) :: e
    !> Output characters (room for d + e + 6 more).
    character(*), intent(inout) :: buf
    !> Characters in use.
    integer, intent(inout) :: pos
    character(len=scratch_len) :: body
    integer(int64) :: m, q
    integer :: w, first, n, status, ex, k, p, a
    logical :: negative, ok, done
    if (e == 3 .and. d == cell_decimals) then
      call cell_digits_fast(x, buf, pos, done)
      if (done) return
    end if
    if (e == 3 .and. d >= 1 .and. d < max_digits) then
      call split(x, negative, m, ex)
      ok = .true.
      k = 0
      q = 0
      if (m /= 0) call significant_digits(m, ex, d + 1, q, k, ok)
      if (ok) then
        p = pos
        if (negative) then
          p = p + 1
          buf(p:p) = "-"
        end if
        call put_digits(q, d + 1, buf(p + 2:p + d + 2))
        buf(p + 1:p + 1) = buf(p + 2:p + 2)
        buf(p + 2:p + 2) = "."
        p = p + d + 2
        if (k < 0) then
          buf(p + 1:p + 2) = "E-"
        else
          buf(p + 1:p + 2) = "E+"
        end if
        a = abs(k)
        buf(p + 3:p + 3) = achar(48 + a / 100)
        a = mod(a, 100)
        buf(p + 4:p + 5) = digit_pairs(2 * a + 1:2 * a + 2)
        pos = p + 5
        return
      end if
    end if
    w = d + e + 6
    call exponent_body(x, d, e, .true., w, body, n, status)
    if (status /= body_ok) then
      call edit_exponent(x, d, e, scientific=.true., text=body(1:w))
      first = verify(body(1:w), " ")
      n = w - first + 1
      body(1:n) = body(first:w)
    end if
    buf(pos + 1:pos + n) = body(1:n)
    pos = pos + n
  end subroutine put_es_compact

  !> round_significant in one pass (no second rounding when the first estimate of the
  !> exponent is one short): |x| = m * 2**e (m /= 0) rounded to n significant digits, q with
  !> 10**(n-1) <= q < 10**n, and the decimal exponent k of its first digit; ok false outside
  !> the exact 128-bit fast path (|x| below ~1e-15 or from ~1e13 up; the caller falls back).
  pure subroutine significant_digits(m, e, n, q, k, ok)
    integer(int64), intent(in) :: m
    integer, intent(in) :: e, n
    integer(int64), intent(out) :: q
    integer, intent(out) :: k
    logical, intent(out) :: ok
    integer(i16) :: p, t, rem, half
    integer(int64) :: r
    integer :: s, sh, top
    !> Where x * 10**s lies between t and t + 1: 0 on t, 1 below t + 1/2, 2 on it, 3 above.
    integer :: fraction
    ok = .false.
    q = 0
    top = e + int(bit_size(m)) - 1 - leadz(m)   ! 2**top <= |x| < 2**(top + 1)
    ! the exponent, or one short of it: floor(top * log10(2)), exact for |top| <= 1200
    k = shifta(top * 78913, 18)
    s = n - 1 - k
    if (s < 0 .or. s > max_pow5) return
    p = int(m, i16) * pow5(s)
    sh = e + s
    if (sh >= 0) then
      if (bit_size(p) - leadz(p) + sh > 126) return
      t = shiftl(p, sh)
      fraction = 0
    else
      sh = -sh
      if (sh > 125) return
      t = shiftr(p, sh)
      rem = p - shiftl(t, sh)
      half = shiftl(1_i16, sh - 1)
      if (rem == 0) then
        fraction = 0
      else if (rem < half) then
        fraction = 1
      else if (rem == half) then
        fraction = 2
      else
        fraction = 3
      end if
    end if
    ! t < 2 * 10**n <= 2 * 10**17: int64 from here on
    q = int(t, int64)
    if (q >= int(pow10(n), int64)) then
      ! |x| >= 10**(k+1): one digit fewer of x * 10**s, rounded from q and what lay below it
      r = mod(q, 10_int64)
      q = q / 10_int64
      k = k + 1
      if (r > 5 .or. (r == 5 .and. (fraction > 0 .or. btest(q, 0)))) q = q + 1
    else if (fraction == 3 .or. (fraction == 2 .and. btest(q, 0))) then
      q = q + 1
    end if
    if (q == int(pow10(n), int64)) then    ! rounded up to the next power of ten
      q = int(pow10(n - 1), int64)
      k = k + 1
    end if
    ok = .true.
  end subroutine significant_digits

  !> put_es_compact's ES20.12E3 for the common magnitudes (1e-10 <= |x| < ~1e11) in double
  !> precision: |x| * 10**s (s = 12 - the decimal exponent, 10**s exact) rounded once by the
  !> multiplication, off the exact product by under 2**-10 (the product is below 10**13), so
  !> the nearest integer is the exact rounding unless the fraction lies within tie_margin of
  !> a half; then, and outside that range, `done` is false, nothing is written and the
  !> exact 128-bit path decides. The text goes straight into buf, without a branch on the
  !> sign: the "-" is always stored and passed over for a negative x; the first digit and
  !> the point, then four and eight digits each made at once in an integer's bytes
  !> (four_digits, eight_digits) and stored whole, then the exponent from a table.
  pure subroutine cell_digits_fast(x, buf, pos, done)
    !> Finite value.
    real(wp), intent(in) :: x
    !> Output characters (room for 20 more).
    character(*), intent(inout) :: buf
    !> Characters in use.
    integer, intent(inout) :: pos
    !> Whether the number was written.
    logical, intent(out) :: done
    integer(int64), parameter :: ten13 = 10000000000000_int64, ten12 = 1000000000000_int64, &
      ten8 = 100000000_int64
    integer(int64) :: bits, q, high
    real(wp) :: a, y, f
    integer :: top, k, s, p, lead, four
    done = .false.
    bits = transfer(x, bits)
    if (bits == 0_int64) then          ! +0 (-0 keeps its sign: the exact path writes it)
      buf(pos + 1:pos + 19) = "0.000000000000E+000"
      pos = pos + 19
      done = .true.
      return
    end if
    a = abs(x)
    top = int(iand(shiftr(bits, 52), 2047_int64)) - 1023
    if (top < -34 .or. top > 36) return
    k = shifta(top * 78913, 18)        ! the decimal exponent, or one short of it
    s = cell_decimals - k
    if (s > max_exact_pow10) return
    y = a * exact_pow10(s)             ! below 2 * 10**13
    q = int(y, int64)                  ! y's whole part (exact: y < 2**53)
    f = y - real(q, wp)                ! its fraction (exact)
    if (abs(f - 0.5_wp) <= tie_margin) return
    if (f > 0.5_wp) q = q + 1_int64
    if (q >= ten13) then               ! |x| >= 10**(k+1), or it rounded up to it
      k = k + 1
      y = a * exact_pow10(s - 1)
      q = int(y, int64)
      f = y - real(q, wp)
      if (abs(f - 0.5_wp) <= tie_margin) return
      if (f > 0.5_wp) q = q + 1_int64
      if (q >= ten13 .or. q < ten12) return
    else if (q < ten12) then
      return
    end if
    p = pos
    buf(p + 1:p + 1) = "-"
    p = p + int(shiftr(bits, 63))      ! past the "-" of a negative x
    high = q / ten8                    ! the first five digits
    lead = int(high) / 10000
    four = int(high) - 10000 * lead
    buf(p + 1:p + 1) = achar(48 + lead)
    buf(p + 2:p + 2) = "."
    buf(p + 3:p + 6) = transfer(four_digits(four), "abcd")
    buf(p + 7:p + 14) = transfer(eight_digits(q - high * ten8), "abcdefgh")
    buf(p + 15:p + 19) = exponent_texts(k)
    pos = p + 19
    done = .true.
  end subroutine cell_digits_fast

  !> A CSV cell or JSON number appended to buf at pos+1.. (pos advanced; room for 24 more):
  !> in a column of whole numbers (flags, counts) a whole value below 1e15 as I0 prints it,
  !> anything else ES20.12E3 without blanks (-0 as 0).
  pure subroutine put_cell_number(x, whole, buf, pos)
    !> Finite value.
    real(wp), intent(in) :: x
    !> True for a column of whole numbers.
    logical, intent(in) :: whole
    !> Output characters.
    character(*), intent(inout) :: buf
    !> Characters in use.
    integer, intent(inout) :: pos
    if (whole) then
      if (abs(x) < whole_limit .and. x == aint(x)) then
        call put_whole(nint(x, kind=int64), buf, pos)
        return
      end if
    end if
    call put_es_compact(x + 0.0_wp, cell_decimals, 3, buf, pos)
  end subroutine put_cell_number

  !> Lines of cells appended to buf at pos+1.. (pos advanced): for each row k of `rows`,
  !> `opening`, put_cell_number of rows(columns(i), k) for every i with `separator` between
  !> them, then `closing` (the line's end included, if any). Room: 20 + len(separator)
  !> characters a cell, len(opening) + len(closing) a row, and 8 more (stored past the
  !> text, and overwritten by what follows).
  !> A cell of the common magnitudes (1e-10 <= |x| < 1e13) is written in the loop: |x| times
  !> the power of ten its binary exponent selects from a table (the table's second half when
  !> the product rounds to 14 digits), rounded to the nearest integer by adding 2**52 (the
  !> product's error is below 2**-10, so the rounding is the exact one unless the product
  !> lies within that of a half; then the exact 128-bit product decides, exact_cell_digits),
  !> its 13 digits made in the bytes of two integers, and the exponent with the separator
  !> stored as one integer from the table; the opening and the closing are one store each;
  !> zero is one copy; whole numbers and other magnitudes go through put_cell_number.
  pure subroutine put_cell_numbers(rows, n_values, n_rows, columns, opening, separator, closing, buf, pos, whole)
    !> Values a row (the leading extent of `rows`).
    integer, intent(in) :: n_values
    !> Rows.
    integer, intent(in) :: n_rows
    !> The rows' values, a row a column (finite where written).
    real(wp), intent(in) :: rows(n_values, n_rows)
    !> Indices into a row of the cells, in order.
    integer, intent(in), contiguous :: columns(:)
    !> Text before a row's first cell: at most 8 characters.
    character(*), intent(in) :: opening
    !> Text between two cells: one or two characters.
    character(*), intent(in) :: separator
    !> Text after a row's last cell: at most 8 characters.
    character(*), intent(in) :: closing
    !> Output characters.
    character(*), intent(inout) :: buf
    !> Characters in use.
    integer, intent(inout) :: pos
    !> Per cell: a column of whole numbers (absent: none is).
    logical, intent(in), contiguous, optional :: whole(:)
    integer(int64), parameter :: ten8 = 100000000_int64, ten13 = 10000000000000_int64
    !> n * 109951163 / 2**40 is n / 10**4 for 0 <= n < 10**8.
    integer(int64), parameter :: by_ten4 = 109951163_int64
    !> n * 6189700196426901375 / 2**89 is n / 10**8 for 0 <= n < 2**63.
    integer(i16), parameter :: by_ten8 = 6189700196426901375_i16
    !> The bits of y + 2**52 below 2**52: y rounded to the nearest integer (y < 2**52).
    integer(int64), parameter :: low52 = shiftl(1_int64, 52) - 1_int64
    real(wp), parameter :: two52 = 2.0_wp**52
    !> |y - q| from this on: the exact product decides the rounding.
    real(wp), parameter :: near_half = 0.5_wp - 2.0_wp**(-10)
    !> The product from this on rounds to 10**13 or more: the table's second half (10**13 -
    !> 1/2 + 2**-9, the next double above the last one that rounds below 10**13).
    real(wp), parameter :: cell_switch = 1.0e13_wp - 0.5_wp + 2.0_wp**(-9)
    !> The products of the fast magnitudes are from this up (0 outside them).
    real(wp), parameter :: ten12 = 1.0e12_wp
    !> The bytes "d." of the first digit d = 0, little-endian ("0" = 48, "." = 46).
    integer, parameter :: zero_point = 48 + 256 * 46
    integer(int64) :: bits, q, high, low, lead, half8, j, sep_text, sep_word, open_word, close_word, p
    integer :: cells(size(columns))
    real(wp) :: x, a, y, f
    integer :: i, k, c, at, n_sep, n_open, n_close
    n_sep = len(separator)
    n_open = len(opening)
    n_close = len(closing)
    sep_text = text_word(separator)
    sep_word = shiftl(sep_text, 40)
    open_word = text_word(opening)
    close_word = text_word(closing)
    ! a whole-number column's index negative
    cells = columns
    if (present(whole)) cells = merge(-columns, columns, whole)
    p = pos
    do k = 1, n_rows
      buf(p + 1:p + 8) = transfer(open_word, "abcdefgh")
      p = p + n_open
      do i = 1, size(cells)
        c = cells(i)
        if (c < 0) then                          ! a whole-number column
          at = int(p)
          call put_cell_number(rows(-c, k), .true., buf, at)
          p = at
          buf(p + 1:p + 8) = transfer(sep_text, "abcdefgh")
          p = p + n_sep
          cycle
        end if
        x = rows(c, k)
        bits = transfer(x, bits)
        j = shiftr(shiftl(bits, 1), 53)           ! the biased binary exponent
        a = abs(x)
        y = a * cell_scales(j)
        if (y >= cell_switch) then
          j = j + 2048_int64
          y = a * cell_scales(j)
        end if
        fast: block
          if (.not. (y >= ten12)) exit fast      ! zero, or not a fast magnitude
          f = y + two52
          q = iand(transfer(f, q), low52)       ! y rounded to the nearest integer
          f = y - (f - two52)                   ! y - q
          if (abs(f) >= near_half) then
            call exact_cell_digits(bits, cell_scale_exponents(j), q)
            if (q >= ten13) exit fast
          end if
          buf(p + 1:p + 1) = "-"
          p = p + shiftr(bits, 63)               ! past the "-" of a negative x
          high = int(shiftr(int(q, i16) * by_ten8, 89))   ! the first five digits
          low = q - high * ten8                  ! the other eight
          lead = shiftr(high * by_ten4, 40)
          half8 = shiftr(low * by_ten4, 40)
          buf(p + 1:p + 2) = transfer(int(zero_point + lead, int16), "ab")
          buf(p + 3:p + 6) = transfer(digit_quads(high - 10000_int64 * lead), "abcd")
          buf(p + 7:p + 10) = transfer(digit_quads(half8), "abcd")
          buf(p + 11:p + 14) = transfer(digit_quads(low - 10000_int64 * half8), "abcd")
          buf(p + 15:p + 22) = transfer(cell_exponent_words(j) + sep_word, "abcdefgh")
          p = p + 19 + n_sep
          cycle
        end block fast
        if (shiftl(bits, 1) == 0_int64) then     ! +-0
          buf(p + 1:p + 19) = "0.000000000000E+000"
          p = p + 19
        else
          at = int(p)
          call put_cell_number(x, .false., buf, at)
          p = at
        end if
        buf(p + 1:p + 8) = transfer(sep_text, "abcdefgh")
        p = p + n_sep
      end do
      if (size(cells) > 0) p = p - n_sep
      buf(p + 1:p + 8) = transfer(close_word, "abcdefgh")
      p = p + n_close
    end do
    pos = int(p)
  end subroutine put_cell_numbers

  !> Up to 8 characters as the bytes of one integer, the first in its lowest byte (stored in
  !> this order on a little-endian machine); the rest zero.
  pure integer(int64) function text_word(text) result(w)
    character(*), intent(in) :: text
    integer :: i
    w = 0
    do i = min(len(text), 8), 1, -1
      w = shiftl(w, 8) + ichar(text(i:i))
    end do
  end function text_word

  !> put_cell_numbers' 13 digits of |x| (a normal double, bits its bits) times 10**s, exactly:
  !> the 128-bit product of its mantissa and 5**s, shifted, rounded to the nearest integer,
  !> ties to even (0 <= s <= 22 and the result below 2**44: the shift lies in 9 .. 125).
  pure subroutine exact_cell_digits(bits, s, q)
    !> The bits of x.
    integer(int64), intent(in) :: bits
    !> The power of ten.
    integer, intent(in) :: s
    !> The result.
    integer(int64), intent(out) :: q
    integer(i16) :: p, t, rem, half
    integer :: sh
    p = int(iand(bits, shiftl(1_int64, 52) - 1_int64) + shiftl(1_int64, 52), i16) * pow5(s)
    sh = 1075 - int(iand(shiftr(bits, 52), 2047_int64)) - s       ! -(e + s)
    t = shiftr(p, sh)
    rem = p - shiftl(t, sh)
    half = shiftl(1_i16, sh - 1)
    if (rem > half .or. (rem == half .and. btest(t, 0))) t = t + 1
    q = int(t, int64)
  end subroutine exact_cell_digits

  !> The 8 decimal digits of 0 <= v < 10**8 as ASCII bytes of one integer, the first digit
  !> in its lowest byte (so stored in this order on a little-endian machine): the halves,
  !> the pairs and the digits each split in parallel in the integer's lanes, dividing by
  !> multiplying (n * 10486 / 2**20 is n / 100 for n < 10**4, n * 103 / 2**10 is n / 10
  !> for n < 100).
  pure integer(int64) function eight_digits(v) result(w)
    integer(int64), intent(in) :: v
    integer(int64) :: merged, hundreds, pairs, tens
    merged = shiftr(v * 109951163_int64, 40)       ! v / 10**4 (exact for v < 10**8)
    merged = merged + shiftl(v - 10000_int64 * merged, 32)
    hundreds = iand(shiftr(merged * 10486_int64, 20), int(z'0000007F0000007F', int64))
    pairs = hundreds + shiftl(merged - 100_int64 * hundreds, 16)
    tens = iand(shiftr(pairs * 103_int64, 10), int(z'000F000F000F000F', int64))
    w = tens + shiftl(pairs - 10_int64 * tens, 8) + int(z'3030303030303030', int64)
  end function eight_digits

  !> The 4 decimal digits of 0 <= v < 10**4 as ASCII bytes of one integer (as eight_digits).
  pure integer function four_digits(v) result(w)
    integer, intent(in) :: v
    integer :: pairs, tens
    pairs = shiftr(v * 10486, 20)
    pairs = pairs + shiftl(v - 100 * pairs, 16)
    tens = iand(shiftr(pairs * 103, 10), int(z'000F000F'))
    w = tens + shiftl(pairs - 10 * tens, 8) + int(z'30303030')
  end function four_digits

  !> Append the whole number q (any sign) to buf at pos+1.. (pos advanced), as I0 prints it.
  pure subroutine put_whole(q, buf, pos)
    !> The number.
    integer(int64), intent(in) :: q
    !> Output characters (room for 20 more).
    character(*), intent(inout) :: buf
    !> Characters in use.
    integer, intent(inout) :: pos
    integer(int64) :: a
    integer :: n
    if (q == -huge(q) - 1_int64) then
      buf(pos + 1:pos + 20) = "-9223372036854775808"
      pos = pos + 20
      return
    end if
    a = abs(q)
    if (q < 0) then
      pos = pos + 1
      buf(pos:pos) = "-"
    end if
    n = digit_count(a)
    call put_digits(a, n, buf(pos + 1:pos + n))
    pos = pos + n
  end subroutine put_whole

end module kinetostat_decimal
