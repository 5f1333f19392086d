!> The exact number writer (kinetostat_decimal) against the compiler's formatted WRITE, byte
!> for byte: 10^4 pseudo-random doubles (10^6 with `tools/test --long`; a fixed seed, so a
!> failure repeats; the first 10^4 are the same in both) over the whole
!> exponent range (random bit patterns, subnormals among them), decimal ties and near-ties,
!> values that round up to a new power of ten, +-0, each through the CSV descriptor
!> ES20.12E3, and every third one through one more descriptor of the output policy in turn
!> (E, ES and F forms).
module test_decimal
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp
  use kinetostat_decimal, only: edit_f, edit_exponent, put_es_compact, put_whole
  use kinetostat_text, only: int_str
  use test_harness, only: test_counts_t, check_true, long_checks, next, hex
  use kinetostat_convert_model, only: deck_number
  implicit none
  private
  public :: run_decimal_tests

  !> Number of random doubles: of the default run, and with `tools/test --long` (the default
  !> run's are its first: the same families and descriptors in the same turn, a third of a
  !> second in the checks' build instead of a second and a half for 10^5).
  integer, parameter :: sample_count = 10000, long_sample_count = 1000000
  !> Mismatches printed at most.
  integer, parameter :: max_shown = 10

  !> One edit descriptor of the policy: letter (F, E, S for ES), width, digits, exponent digits.
  type :: descriptor_t
    character :: letter
    integer :: w, d, e
  end type descriptor_t

  !> The descriptors kinetostat_format uses (and a few narrow ones for the '*' and
  !> leading-zero rules).
  type(descriptor_t), parameter :: descriptors(*) = [ &
    descriptor_t("S", 18, 9, 0), descriptor_t("S", 18, 9, 3), descriptor_t("S", 14, 6, 0), &
    descriptor_t("S", 14, 5, 3), descriptor_t("S", 10, 2, 0), descriptor_t("S", 10, 1, 3), &
    descriptor_t("S", 12, 4, 0), descriptor_t("S", 12, 3, 3), descriptor_t("S", 9, 1, 0), &
    descriptor_t("E", 12, 3, 0), descriptor_t("E", 12, 3, 3), descriptor_t("E", 9, 3, 0), &
    descriptor_t("E", 10, 3, 0), descriptor_t("F", 64, 2, 0), descriptor_t("F", 64, 3, 0), &
    descriptor_t("F", 64, 4, 0), descriptor_t("F", 64, 5, 0), descriptor_t("F", 11, 4, 0), &
    descriptor_t("F", 5, 2, 0), descriptor_t("F", 4, 2, 0), descriptor_t("F", 8, 0, 0)]

contains

  subroutine run_decimal_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_fixed_cases(t)
    call test_random(t)
    call test_cell_ties(t)
    call test_whole(t)
    call test_deck_number(t)
  end subroutine run_decimal_tests

  !> The numbers of a converted deck (kinetostat convert): each reads back to the same double
  !> (10^4 random bit patterns, finite ones; the writer takes the first digit count that does),
  !> and the plain and exponent forms of fixed cases.
  subroutine test_deck_number(t)
    type(test_counts_t), intent(inout) :: t
    integer(int64) :: state, bits
    real(wp) :: x, back
    integer :: i, bad, ios
    character(len=:), allocatable :: text, shown
    bad = 0
    shown = ""
    state = 88172645463325252_int64
    do i = 1, 10000
      state = ieor(state, ishft(state, 13)); state = ieor(state, ishft(state, -7)); state = ieor(state, ishft(state, 17))
      bits = state
      x = transfer(bits, x)
      if (.not. ieee_is_finite(x)) cycle
      text = deck_number(x)
      read (text, *, iostat=ios) back
      if (ios /= 0 .or. back /= x) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" "//text
      end if
    end do
    call check_true(t, "deck_number: 10^4 random doubles read back exactly", bad == 0, "not:"//shown)
    call check_true(t, "deck_number: plain forms", deck_number(0.1_wp) == "0.1" .and. deck_number(-0.34_wp) == "-0.34" &
      .and. deck_number(12.0_wp) == "12" .and. deck_number(1.5e-7_wp) == "1.5e-7" .and. deck_number(0.0_wp) == "0" &
      .and. deck_number(0.1_wp + 0.2_wp) == "0.30000000000000004" .and. deck_number(2.0e20_wp) == "2e20" &
      .and. deck_number(1.0e-5_wp) == "0.00001", &
      deck_number(0.1_wp)//" "//deck_number(-0.34_wp)//" "//deck_number(12.0_wp)//" "//deck_number(1.5e-7_wp)//" "// &
      deck_number(0.1_wp + 0.2_wp)//" "//deck_number(2.0e20_wp)//" "//deck_number(1.0e-5_wp))
  end subroutine test_deck_number

  !> The cases named in the spec of the writer, each through every descriptor.
  subroutine test_fixed_cases(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: cases(*) = [0.0_wp, -0.0_wp, 0.125_wp, 0.375_wp, 2.5_wp, -0.001_wp, 0.005_wp, &
      9.9999999999995_wp, 9.99999999999949_wp, 99.995_wp, 0.995_wp, 9.9996e99_wp, 1.0e-100_wp, 1.0e300_wp, &
      huge(1.0_wp), tiny(1.0_wp), 4.9406564584124654e-324_wp, 1.0e30_wp, 999999.995_wp, 1.0e22_wp, 1.0e23_wp]
    integer :: i, j, bad
    character(len=:), allocatable :: shown
    bad = 0
    allocate (character(len=0) :: shown) ! not shown = "" (gcc's -Wmaybe-uninitialized)
    do i = 1, size(cases)
      do j = 1, size(descriptors)
        call compare(cases(i), descriptors(j), bad, shown)
      end do
    end do
    call check_true(t, "decimal: named cases through every descriptor", bad == 0, shown)
  end subroutine test_fixed_cases

  !> 10^4 (--long: 10^6) doubles of five families, each through ES20.12E3 and one descriptor
  !> in turn.
  subroutine test_random(t)
    type(test_counts_t), intent(inout) :: t
    integer(int64) :: state
    real(wp) :: x
    integer :: i, bad, k
    character(len=:), allocatable :: shown
    character(len=20) :: mine, theirs
    character(len=32) :: compact
    integer :: pos, n
    n = merge(long_sample_count, sample_count, long_checks())
    state = 14_int64
    bad = 0
    allocate (character(len=0) :: shown) ! not shown = "" (gcc's -Wmaybe-uninitialized)
    k = 0
    do i = 1, n
      x = sample(state, i)
      call edit_exponent(x, 12, 3, scientific=.true., text=mine)
      write (theirs, '(es20.12e3)') x
      pos = 0
      call put_es_compact(x, 12, 3, compact, pos)
      if (mine /= theirs .or. compact(1:pos) /= trim(adjustl(theirs))) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" ["//hex(x)//" ES20.12E3 '"//mine//"' vs '"//theirs//"']"
      end if
      if (mod(i, 3) /= 0) cycle
      k = mod(k, size(descriptors)) + 1
      call compare(x, descriptors(k), bad, shown)
    end do
    call check_true(t, "decimal: "//int_str(n)//" random doubles equal the compiler's formatted WRITE", bad == 0, &
                    "mismatches "//int_str(bad)//":"//shown)
  end subroutine test_random

  !> The CSV cell (ES20.12E3 without blanks) where its double-precision rounding must give
  !> way to the exact one: 13-digit decimals plus a half unit of the 13th digit (a tie in
  !> decimal, never exactly one in binary but within an ulp of it) nudged by 0 to +-3 ulp,
  !> 13-digit decimals and their neighbours, and magnitudes 1e-11 .. 1e12 uniform in the
  !> logarithm, both signs: 3 * 10^4 values (--long: 3 * 10^6), each against the compiler's
  !> formatted WRITE.
  subroutine test_cell_ties(t)
    type(test_counts_t), intent(inout) :: t
    integer(int64) :: state, digits13
    real(wp) :: x, u
    integer :: i, j, bad, n, pos, expo
    character(len=:), allocatable :: shown
    character(len=20) :: theirs
    character(len=32) :: compact
    n = 3 * merge(long_sample_count, sample_count, long_checks())
    state = 37_int64
    bad = 0
    allocate (character(len=0) :: shown)
    do i = 1, n
      digits13 = 1000000000000_int64 + mod(abs(next(state)), 9000000000000_int64)
      expo = int(mod(abs(next(state)), 24_int64)) - 23
      select case (mod(i, 3))
      case (0) ! a decimal tie of the 13th digit, nudged
        x = (real(digits13, wp) + 0.5_wp) * 10.0_wp**expo
        do j = 1, int(mod(abs(next(state)), 7_int64)) - 3
          x = nearest(x, 1.0_wp)
        end do
        do j = 1, 3 - int(mod(abs(next(state)), 7_int64))
          x = nearest(x, -1.0_wp)
        end do
      case (1) ! a 13-digit decimal, or a neighbour
        x = real(digits13, wp) * 10.0_wp**expo
        if (btest(state, 5)) x = nearest(x, merge(1.0_wp, -1.0_wp, btest(state, 6)))
      case default
        u = real(shiftr(next(state), 11), wp) * 2.0_wp**(-53)
        x = 10.0_wp**(23.0_wp * u - 11.0_wp)
      end select
      if (btest(state, 9)) x = -x
      write (theirs, '(es20.12e3)') x
      pos = 0
      call put_es_compact(x, 12, 3, compact, pos)
      if (compact(1:pos) /= trim(adjustl(theirs))) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" ["//hex(x)//" '"//compact(1:pos)//"' vs '"//trim(adjustl(theirs))//"']"
      end if
    end do
    call check_true(t, "decimal: "//int_str(n)//" CSV cells at and near 13-digit ties equal the compiler's ES20.12E3", &
                    bad == 0, "mismatches "//int_str(bad)//":"//shown)
  end subroutine test_cell_ties

  !> put_whole against I0.
  subroutine test_whole(t)
    type(test_counts_t), intent(inout) :: t
    integer(int64), parameter :: cases(*) = [0_int64, 1_int64, -1_int64, 9_int64, 10_int64, 99_int64, &
      100_int64, -12345_int64, 999999999999999_int64, huge(1_int64), -huge(1_int64), -huge(1_int64) - 1_int64]
    character(len=32) :: mine, theirs
    integer :: i, pos, bad
    bad = 0
    do i = 1, size(cases)
      pos = 0
      call put_whole(cases(i), mine, pos)
      write (theirs, '(i0)') cases(i)
      if (mine(1:pos) /= trim(theirs)) bad = bad + 1
    end do
    call check_true(t, "decimal: whole numbers equal I0", bad == 0, int_str(bad)//" differ")
  end subroutine test_whole

  !> One value through one descriptor, mine against the compiler's.
  subroutine compare(x, dsc, bad, shown)
    real(wp), intent(in) :: x
    type(descriptor_t), intent(in) :: dsc
    integer, intent(inout) :: bad
    character(len=:), allocatable, intent(inout) :: shown
    character(len=dsc%w) :: mine, theirs, fitted
    character(len=24) :: fmt
    logical :: fits
    select case (dsc%letter)
    case ("F")
      call edit_f(x, dsc%d, mine)
      write (fmt, '("(f",i0,".",i0,")")') dsc%w, dsc%d
      ! the form with `fits`: the same text when it leaves a blank in front, else nothing
      fitted = "unset"
      call edit_f(x, dsc%d, fitted, fits)
      write (theirs, fmt) x
      if (fits .neqv. (theirs(1:1) == " ")) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" ["//hex(x)//" "//trim(fmt)//" fits "//merge("T", "F", fits)// &
          " for '"//theirs//"']"
      else if (fits .and. fitted /= theirs) then
        bad = bad + 1
        if (bad <= max_shown) shown = shown//" ["//hex(x)//" "//trim(fmt)//" fits '"//fitted//"' vs '"//theirs//"']"
      end if
    case ("E")
      call edit_exponent(x, dsc%d, dsc%e, scientific=.false., text=mine)
      write (fmt, '("(e",i0,".",i0,"e",i0,")")') dsc%w, dsc%d, dsc%e
      if (dsc%e == 0) write (fmt, '("(e",i0,".",i0,")")') dsc%w, dsc%d
    case default
      call edit_exponent(x, dsc%d, dsc%e, scientific=.true., text=mine)
      write (fmt, '("(es",i0,".",i0,"e",i0,")")') dsc%w, dsc%d, dsc%e
      if (dsc%e == 0) write (fmt, '("(es",i0,".",i0,")")') dsc%w, dsc%d
    end select
    write (theirs, fmt) x
    if (mine /= theirs) then
      bad = bad + 1
      if (bad <= max_shown) shown = shown//" ["//hex(x)//" "//trim(fmt)//" '"//mine//"' vs '"//theirs//"']"
    end if
  end subroutine compare

  !> The i-th sample: a family chosen by i, values drawn from the generator.
  function sample(state, i) result(x)
    integer(int64), intent(inout) :: state
    integer, intent(in) :: i
    real(wp) :: x
    integer(int64) :: bits
    real(wp) :: u
    integer :: digits, expo
    bits = next(state)
    select case (mod(i, 6))
    case (0) ! any finite bit pattern: the whole exponent range, both signs
      x = transfer(bits, x)
      if (.not. ieee_is_finite(x)) x = transfer(ishft(bits, -12), x)
    case (1) ! subnormals and the smallest normals
      x = transfer(iand(bits, int(z'801FFFFFFFFFFFFF', int64)), x)
    case (2) ! a short decimal: an exact or near tie of some descriptor, nudged by 0 or +-1 ulp
      digits = int(mod(abs(next(state)), 10_int64)) + 1
      expo = int(mod(abs(next(state)), 40_int64)) - 20
      x = real(mod(abs(bits), 10_int64**digits), wp) * 10.0_wp**expo + 5.0_wp * 10.0_wp**(expo - 1)
      select case (mod(abs(next(state)), 3_int64))
      case (1); x = nearest(x, 1.0_wp)
      case (2); x = nearest(x, -1.0_wp)
      case default ! the decimal as it is
      end select
      if (btest(bits, 62)) x = -x
    case (3) ! just below a power of ten: rounds up to a new power at some digit count
      expo = int(mod(abs(bits), 60_int64)) - 30
      digits = int(mod(abs(next(state)), 16_int64)) + 1
      x = 10.0_wp**expo * (1.0_wp - 0.5_wp * 10.0_wp**(-digits))
      x = nearest(x, real(mod(abs(next(state)), 3_int64) - 1, wp) + 0.5_wp)
    case (4) ! dyadic fractions: exact decimal ties (0.125, 2.5, ...)
      x = real(mod(abs(bits), 100000_int64), wp) / 2.0_wp**int(mod(abs(next(state)), 20_int64))
    case default ! magnitudes of results: 1e-8 .. 1e22, uniform in the logarithm
      u = real(shiftr(bits, 11), wp) * 2.0_wp**(-53)
      x = 10.0_wp**(30.0_wp * u - 8.0_wp)
      if (btest(bits, 3)) x = -x
    end select
  end function sample

end module test_decimal
