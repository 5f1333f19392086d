!> Gear tests: textbook hand cases of every formula (spur, helical, bevel, planetary), spur =
!> helical with beta = 0, the two-stage reducer's output torque from forces = from power and
!> its intermediate-shaft resultant by hand, self-checks of the example decks.
module test_gears
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_gears, only: gear_stage_t, gear_result_t, gear_pair, gear_series, gear_planetary_step, &
    gear_spur, gear_helical, gear_bevel, gear_planetary
  use kinetostat_gears_deck, only: gears_deck_t, read_gears_deck
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_gears_layout, only: gears_solve
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_gears_tests

  !> Tolerances of the hand cases: relative 1e-12, absolute 1e-9 N (or N*m).
  real(wp), parameter :: rtol = 1.0e-12_wp, atol = 1.0e-9_wp

contains

  subroutine run_gears_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_spur_hand(t)
    call test_helical_hand(t)
    call test_spur_is_helical_beta0(t)
    call test_bevel_hand(t)
    call test_reducer(t)
    call test_planetary_hand(t)
    call test_example_decks(t)
  end subroutine run_gears_tests

  !> Spur, M1 = 100 N*m, z1 = 20, m = 5 mm -> dw1 = 100 mm: Ft = 2000 N,
  !> Fr = 2000*tan(20) = 727.9404685 N, Fn = 2000/cos(20) = 2128.3555450 N; M2 = -u*M1.
  subroutine test_spur_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st
    type(gear_result_t) :: r
    st = gear_stage_t(kind=gear_spur, z1=20, z2=50, dw1=0.1_wp, alpha_w=20.0_wp * deg_to_rad)
    r = gear_pair(st, 100.0_wp, [0.0_wp, 0.0_wp])
    call check_close(t, "spur Ft = 2M/dw", 2000.0_wp, r%ft, rtol, atol)
    call check_close(t, "spur Fr = Ft tan(alpha_w)", 727.9404685324047_wp, r%fr1, 1.0e-12_wp, atol)
    call check_close(t, "spur Fn = Ft/cos(alpha_w)", 2128.355544951824_wp, r%fn, 1.0e-12_wp, atol)
    call check_close(t, "spur Fa = 0", 0.0_wp, r%fa1, 0.0_wp, 0.0_wp)
    call check_close(t, "spur |F12| = Fn (planar, along the line of action)", r%fn, hypot(r%f12(1), r%f12(2)), rtol, atol)
    ! gamma = 0: F12 = (-Fr, -Ft): radial towards O1, tangential against M1 (CCW)
    call check_close(t, "spur F12x = -Fr", -r%fr1, r%f12(1), rtol, atol)
    call check_close(t, "spur F12y = -Ft", -2000.0_wp, r%f12(2), rtol, atol)
    call check_close(t, "spur dw2 = dw1*z2/z1, mm", 250.0_wp, r%dw2 * 1.0e3_wp, rtol, atol)
    call check_close(t, "spur M2 from forces = -u*M1", -250.0_wp, r%m2, rtol, atol)
    call check_true(t, "spur self-check", r%residual <= 1.0e-12_wp .and. r%mismatch <= 1.0e-12_wp, "residual/mismatch")
  end subroutine test_spur_hand

  !> Helical, same pair with beta = 15 deg: Fa = Ft*tan(15) = 535.8983849 N,
  !> Fr = Ft*tan(20)/cos(15) = 753.6240 N, Fn = Ft/(cos(20)*cos(15)) = 2203.4514 N.
  subroutine test_helical_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st
    type(gear_result_t) :: r
    st = gear_stage_t(kind=gear_helical, z1=20, z2=50, dw1=0.1_wp, alpha_w=20.0_wp * deg_to_rad, &
                      beta=15.0_wp * deg_to_rad)
    r = gear_pair(st, 100.0_wp, [0.0_wp, 0.0_wp])
    call check_close(t, "helical Ft", 2000.0_wp, r%ft, rtol, atol)
    call check_close(t, "helical Fa = Ft tan(beta)", 2000.0_wp * 0.2679491924311227_wp, r%fa1, 1.0e-12_wp, atol)
    call check_close(t, "helical Fr = Ft tan(alpha_w)/cos(beta)", 727.9404685324047_wp / 0.9659258262890683_wp, &
                     r%fr1, 1.0e-12_wp, atol)
    call check_close(t, "helical Fn = Ft/(cos alpha_w cos beta)", &
                     2000.0_wp / (0.9396926207859084_wp * 0.9659258262890683_wp), r%fn, 1.0e-12_wp, atol)
    call check_close(t, "helical Fn^2 = Ft^2 + Fr^2 + Fa^2", r%fn**2, r%ft**2 + r%fr1**2 + r%fa1**2, 1.0e-12_wp, atol)
  end subroutine test_helical_hand

  !> Spur and helical with beta = 0 give the same forces, vectors and torques.
  subroutine test_spur_is_helical_beta0(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st
    type(gear_result_t) :: a, b
    st = gear_stage_t(kind=gear_spur, z1=17, z2=61, dw1=0.068_wp, alpha_w=22.5_wp * deg_to_rad, &
                      gamma=37.0_wp * deg_to_rad)
    a = gear_pair(st, -73.0_wp, [0.01_wp, -0.02_wp])
    st%kind = gear_helical
    st%beta = 0.0_wp
    b = gear_pair(st, -73.0_wp, [0.01_wp, -0.02_wp])
    call check_close(t, "spur = helical(beta 0): Ft", a%ft, b%ft, 0.0_wp, 0.0_wp)
    call check_close(t, "spur = helical(beta 0): Fr", a%fr1, b%fr1, 1.0e-15_wp, 0.0_wp)
    call check_close(t, "spur = helical(beta 0): Fa", a%fa1, b%fa1, 0.0_wp, 0.0_wp)
    call check_close(t, "spur = helical(beta 0): Fn", a%fn, b%fn, 1.0e-15_wp, 0.0_wp)
    call check_close(t, "spur = helical(beta 0): F12x", a%f12(1), b%f12(1), 1.0e-15_wp, 1.0e-12_wp)
    call check_close(t, "spur = helical(beta 0): F12y", a%f12(2), b%f12(2), 1.0e-15_wp, 1.0e-12_wp)
    call check_close(t, "spur = helical(beta 0): M2", a%m2, b%m2, 1.0e-15_wp, 1.0e-12_wp)
  end subroutine test_spur_is_helical_beta0

  !> Straight bevel, z1 = 20, z2 = 40 (delta1 = atan(1/2)), d_m1 = 70 mm, M1 = 80 N*m:
  !> Ft = 2285.714286 N, Fr1 = Ft tan20 cos(delta1) = 744.1025697 N,
  !> Fa1 = Ft tan20 sin(delta1) = 372.0512848 N, Fr2 = Fa1, Fa2 = Fr1, Fn = Ft/cos20.
  subroutine test_bevel_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st
    type(gear_result_t) :: r
    real(wp) :: ft
    st = gear_stage_t(kind=gear_bevel, z1=20, z2=40, dw1=0.07_wp, alpha_w=20.0_wp * deg_to_rad, &
                      delta1=atan(0.5_wp))
    r = gear_pair(st, 80.0_wp, [0.0_wp, 0.0_wp])
    ft = 160.0_wp / 0.07_wp
    call check_close(t, "bevel Ft = 2M/d_m", ft, r%ft, rtol, atol)
    call check_close(t, "bevel Fr1", ft * 0.36397023426620234_wp * 2.0_wp / sqrt(5.0_wp), r%fr1, 1.0e-12_wp, atol)
    call check_close(t, "bevel Fa1", ft * 0.36397023426620234_wp / sqrt(5.0_wp), r%fa1, 1.0e-12_wp, atol)
    call check_close(t, "bevel Fr2 = Fa1", r%fa1, r%fr2, 1.0e-12_wp, atol)
    call check_close(t, "bevel Fa2 = Fr1", r%fr1, r%fa2, 1.0e-12_wp, atol)
    call check_close(t, "bevel Fn = Ft/cos(alpha)", ft / 0.9396926207859084_wp, r%fn, 1.0e-12_wp, atol)
    call check_close(t, "bevel M2 = u*M1", 160.0_wp, r%m2, rtol, atol)
  end subroutine test_bevel_hand

  !> Two spur stages in series, both centre lines along x (gamma = 0): M1 = 50 N*m,
  !> 20/40 m = 3, then 18/54 m = 4. M_out = M1*(z2*z4)/(z1*z3) = 300 N*m, same sense as M1.
  !> Intermediate shaft: F21 = (Fr1, Ft1), F34 = (-Fr3, Ft3) with M3 = -100 N*m, so its support
  !> carries (Fr3 - Fr1, -(Ft1 + Ft3)): Ft1 = 1666.67 N, Ft3 = 2777.78 N.
  subroutine test_reducer(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st(2)
    type(gear_result_t) :: r(2)
    real(wp) :: ft1, ft3, fr1, fr3, tan20
    tan20 = 0.36397023426620234_wp
    st(1) = gear_stage_t(kind=gear_spur, z1=20, z2=40, dw1=0.06_wp, alpha_w=20.0_wp * deg_to_rad)
    st(2) = gear_stage_t(kind=gear_spur, z1=18, z2=54, dw1=0.072_wp, alpha_w=20.0_wp * deg_to_rad)
    call gear_series(st, 50.0_wp, r)
    ft1 = 100.0_wp / 0.06_wp
    ft3 = 200.0_wp / 0.072_wp
    fr1 = ft1 * tan20
    fr3 = ft3 * tan20
    call check_close(t, "reducer M_out from forces", 300.0_wp, r(2)%m2, rtol, atol)
    call check_close(t, "reducer M_out from power = M1 z2 z4/(z1 z3)", 50.0_wp * 40 * 54 / (20 * 18), &
                     r(2)%m2_power, rtol, atol)
    call check_close(t, "reducer torque: forces = power", r(2)%m2_power, r(2)%m2, 1.0e-12_wp, atol)
    call check_close(t, "reducer intermediate torque M2 = -u12 M1", -100.0_wp, r(1)%m2, rtol, atol)
    call check_close(t, "reducer stage-2 input = M2", -100.0_wp, r(2)%m1, rtol, atol)
    call check_close(t, "reducer shaft 23 support x = Fr3 - Fr1", fr3 - fr1, r(1)%fs2(1), 1.0e-12_wp, atol)
    call check_close(t, "reducer shaft 23 support y = -(Ft1 + Ft3)", -(ft1 + ft3), r(1)%fs2(2), 1.0e-12_wp, atol)
    call check_close(t, "reducer output support = F34 (x)", r(2)%f12(1), r(2)%fs2(1), rtol, atol)
    call check_close(t, "reducer |F12| = M1/(r_w1 cos alpha_w)", 50.0_wp / (0.03_wp * 0.9396926207859084_wp), &
                     hypot(r(1)%f12(1), r(1)%f12(2)), 1.0e-12_wp, atol)
    call check_close(t, "reducer O4 x = a_w1 + a_w2", 0.09_wp + 0.144_wp, r(2)%o2(1), rtol, atol)
    call check_true(t, "reducer self-check", maxval(r%residual) <= 1.0e-12_wp .and. maxval(r%mismatch) <= 1.0e-12_wp, &
                    "residual/mismatch above 1e-12")
  end subroutine test_reducer

  !> Planetary: sun z1 = 24, satellites z2 = 24, ring z3 = 72, k = 3, dw1 = 60 mm, M1 = 120 N*m:
  !> F12 = 2*120/(0.06*3*cos20) = 1418.903697 N, u_1H = 1 + 72/24 = 4, M_H = 480 N*m,
  !> F2H = 2*Ft = 2666.67 N (tangential), housing moment M1 - M_H = -360 N*m; the floating sun
  !> carries no radial load for k = 3, but the whole F12 for k = 1.
  subroutine test_planetary_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_stage_t) :: st
    type(gear_result_t) :: r
    st = gear_stage_t(kind=gear_planetary, z1=24, z2=24, z3=72, k=3, dw1=0.06_wp, alpha_w=20.0_wp * deg_to_rad, &
                      alpha_w23=20.0_wp * deg_to_rad, gamma=90.0_wp * deg_to_rad)
    r = gear_planetary_step(st, 120.0_wp)
    call check_close(t, "planetary F12 = 2M1/(dw1 k cos alpha_w)", 240.0_wp / (0.06_wp * 3 * 0.9396926207859084_wp), &
                     hypot(r%f12(1), r%f12(2)), 1.0e-12_wp, atol)
    call check_close(t, "planetary u_1H = 1 + z3/z1", 4.0_wp, r%u, rtol, 0.0_wp)
    call check_close(t, "planetary M_H from forces", 480.0_wp, r%m2, 1.0e-12_wp, atol)
    call check_close(t, "planetary M_H power", 480.0_wp, r%m2_power, rtol, atol)
    call check_close(t, "planetary |F2H| = 2 Ft", 2.0_wp * 40.0_wp / 0.03_wp, hypot(r%f2h(1), r%f2h(2)), 1.0e-12_wp, atol)
    call check_close(t, "planetary F2H along x (satellite at 90 deg)", 0.0_wp, r%f2h(2), 0.0_wp, 1.0e-9_wp)
    call check_close(t, "planetary satellite balance x", 0.0_wp, -r%f12(1) + r%f23(1) + r%f2h(1), 0.0_wp, 1.0e-9_wp)
    call check_close(t, "planetary satellite balance y", 0.0_wp, -r%f12(2) + r%f23(2) + r%f2h(2), 0.0_wp, 1.0e-9_wp)
    call check_close(t, "planetary housing from forces", -360.0_wp, r%m_house, 1.0e-12_wp, atol)
    call check_close(t, "planetary housing M1 - M_H", -360.0_wp, r%m_house_power, rtol, atol)
    call check_close(t, "planetary sun support (k = 3)", 0.0_wp, hypot(r%fs1(1), r%fs1(2)), 0.0_wp, 1.0e-9_wp)
    ! one satellite: the sun's support takes -F12; unequal mesh angles tilt F2H
    st%k = 1
    st%alpha_w23 = 25.0_wp * deg_to_rad
    r = gear_planetary_step(st, 120.0_wp)
    call check_close(t, "planetary k=1 F12 = 2M1/(dw1 cos alpha_w)", 240.0_wp / (0.06_wp * 0.9396926207859084_wp), &
                     hypot(r%f12(1), r%f12(2)), 1.0e-12_wp, atol)
    call check_close(t, "planetary k=1 sun support = -F12", -r%f12(1), r%fs1(1), 1.0e-12_wp, atol)
    call check_close(t, "planetary k=1 F2H radial = Fr23 - Fr12", &
                     (4000.0_wp * (tan(25.0_wp * deg_to_rad) - 0.36397023426620234_wp)), r%f2h(2), 1.0e-12_wp, atol)
    call check_close(t, "planetary k=1 M_H still M1 u_1H", 480.0_wp, r%m2, 1.0e-12_wp, atol)
  end subroutine test_planetary_hand

  !> Every example deck: read, solve, residual and mismatch <= 1e-9; dw1 = z1*m.
  subroutine test_example_decks(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: decks(3) = [character(len=24) :: "data/gears_reducer.nml", &
      "data/gears_planetary.nml", "data/gears_bevel.nml"]
    type(gears_deck_t) :: deck
    type(gear_result_t), allocatable :: res(:)
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    integer :: i
    do i = 1, size(decks)
      call load_deck(trim(decks(i)), source, error)
      if (.not. allocated(error)) call read_gears_deck(source, deck, error)
      call check_true(t, "read "//trim(decks(i)), .not. allocated(error), "deck rejected")
      if (allocated(error)) cycle
      call gears_solve(deck, res)
      call check_true(t, trim(decks(i))//" residual <= 1e-9", maxval(res%residual) <= 1.0e-9_wp, "too large")
      call check_true(t, trim(decks(i))//" torque mismatch <= 1e-9", maxval(res%mismatch) <= 1.0e-9_wp, "too large")
      if (i == 3) call check_close(t, "bevel deck d_m1 = z1*m", 0.07_wp, deck%st(1)%dw1, rtol, 0.0_wp)
    end do
  end subroutine test_example_decks

end module test_gears
