!> Counterweight balancing of an `&linkage` deck (`kinetostat balance`, docs/shaking.md): the
!> method of `&assur` decks (kinetostat_assur_balance) on the links of any linkage. Full
!> balance: the total first moment of mass sum m_i S_i must not change with the motion; a
!> link turning about a pivot P on the frame adds m_i P + R(theta_i) w_i, w_i its first moment
!> about P in its reference orientation, so the w_i of those links and a constant C solve in
!> the least-squares sense over a turn of the first drive (72 positions; over the deck's steps
!> when the linkage does not go round, or with several drives or a sliding drive)
!> sum R(theta_i) w_i - C = -(the rest of the first moment); a residual means full balance is
!> impossible (a link whose reference point moves, such as a slider). Crank balance: the first
!> drive's link's own centre of mass onto its pivot. Partial balance of a slider-crank: the
!> crank's counterweight for its rotating mass and a fraction of its reciprocating mass.
module kinetostat_linkage_balance
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_usage, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_format, only: full_number, short_number
  use kinetostat_labels, only: lang_ru, unit_symbol, in_language
  use kinetostat_override, only: override_t, append_override
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_least_squares, only: least_squares
  use kinetostat_vec2, only: rotate
  use kinetostat_linkage, only: linkage_t, linkage_work_t, pair_r, pair_p, linkage_reference_pose, linkage_assemble, &
    point_position
  use kinetostat_linkage_deck, only: linkage_deck_t, linkage_drive_values
  implicit none
  private
  public :: linkage_balance

  !> The methods (the codes of kinetostat_assur_balance's balance_full, _crank, _partial).
  integer, parameter :: method_full = 1, method_crank = 2, method_partial = 3
  !> Their names, in the order of their codes.
  character(*), parameter :: method_names(*) = [character(len=7) :: "full", "crank", "partial"]
  !> Positions of the sample turn (every 5 deg).
  integer, parameter :: sample_count = 72
  !> Full balance exists when the least-squares residual is at most this times the unbalanced
  !> travel of the first moment.
  real(wp), parameter :: balance_rel = 1.0e-9_wp

contains

  !> The counterweights of `method` (1 full, 2 crank, 3 partial) for the validated deck: the
  !> deck assignments that add them (link(i)%m with the counterweight in a comment, %j, %s) and
  !> the report's lines.
  pure subroutine linkage_balance(deck, method, fraction, lang, overrides, report, error)
    type(linkage_deck_t), intent(in) :: deck
    integer, intent(in) :: method
    !> Partial method: the fraction of the reciprocating mass balanced, 0..1.
    real(wp), intent(in) :: fraction
    integer, intent(in) :: lang
    type(override_t), allocatable, intent(out) :: overrides(:)
    type(text_buffer_t), intent(inout) :: report
    !> No balance of that kind exists (exit 3), or the deck does not fit the method (exit 1).
    type(error_t), allocatable, intent(out) :: error
    real(wp), allocatable :: w_new(:, :), pivot(:, :)
    logical, allocatable :: carries(:)
    integer :: nl, i, crank
    nl = size(deck%mech%links)
    allocate (overrides(0), w_new(2, nl), pivot(2, nl), carries(nl))
    w_new = 0.0_wp
    carries = .false.
    call pivots(deck%mech, pivot, carries)
    crank = 0
    associate (pr => deck%mech%pairs(deck%mech%drives(1)%pair))
      if (pr%kind == pair_r .and. pr%b == 0) crank = pr%a
    end associate
    select case (method)
    case (method_crank, method_partial)
      if (crank == 0) then
        call fatal_error(error, exit_usage, "balance --method "//trim(method_names(method))//" needs a crank: a "// &
          "first drive that turns a link on the frame")
        return
      end if
      carries = .false.
      carries(crank) = .true.
      if (method == method_crank) then
        call report%put(in_language("crank balance: the crank's own centre of mass onto its pivot", &
          "уравновешивание кривошипа: центр масс"// &
            " кривошипа переносится на ось его вращения", lang))
      else
        call partial(crank, w_new(:, crank), report, error)
        if (allocated(error)) return
      end if
    case default
      call full_balance(deck, pivot, lang, w_new, carries, report, error)
      if (allocated(error)) return
    end select
    do i = 1, nl
      if (carries(i)) call add_counterweight(deck, i, pivot(:, i), w_new(:, i), method, lang, overrides, report)
    end do
    if (size(overrides) == 0) call report%put(in_language("no counterweight needed: the deck is balanced already", &
      "противовесы не нужны: механизм уже уравновешен", lang))
  contains
    !> The slider-crank's partial balance: the crank's new first moment about its pivot.
    pure subroutine partial(k, w, rep, err)
      integer, intent(in) :: k
      real(wp), intent(out) :: w(2)
      type(text_buffer_t), intent(inout) :: rep
      type(error_t), allocatable, intent(out) :: err
      integer :: rod, slider, ip, jp
      real(wp) :: b(2), c(2), share, m_rec, m_rot, r, l, omega
      character(len=:), allocatable :: kg, m, n_unit
      w = 0.0_wp
      rod = 0
      slider = 0
      ! the rod: the link joined to the crank by a turning pair; the slider: joined to the rod
      ! by a turning pair and to the frame by a sliding pair
      do ip = 1, size(deck%mech%pairs)
        associate (pr => deck%mech%pairs(ip))
          if (pr%kind == pair_r .and. (pr%a == k .or. pr%b == k) .and. pr%a + pr%b - k > 0) then
            rod = pr%a + pr%b - k
            b = pr%at
          end if
        end associate
      end do
      if (rod > 0) then
        do ip = 1, size(deck%mech%pairs)
          associate (pr => deck%mech%pairs(ip))
            if (pr%kind /= pair_r .or. .not. (pr%a == rod .or. pr%b == rod) .or. pr%a + pr%b - rod == k) cycle
            if (pr%a + pr%b - rod == 0) cycle
            do jp = 1, size(deck%mech%pairs)
              associate (pg => deck%mech%pairs(jp))
                if (pg%kind == pair_p .and. pg%a + pg%b == pr%a + pr%b - rod .and. min(pg%a, pg%b) == 0) then
                  slider = pr%a + pr%b - rod
                  c = pr%at
                end if
              end associate
            end do
          end associate
        end do
      end if
      if (size(deck%mech%links) /= 3 .or. rod == 0 .or. slider == 0) then
        call fatal_error(err, exit_usage, "--method partial balances a slider-crank: a crank on the frame, a rod "// &
          "and a slider on a guide of the frame; use --method full or crank")
        return
      end if
      associate (pc => pivot(:, k), lr => deck%mech%links(rod), ls => deck%mech%links(slider))
        l = norm2(c - b)
        r = norm2(b - pc)
        ! the rod as two masses: at the crank pin and at the slider's pin (static equivalent)
        share = dot_product(lr%s - b, c - b) / l**2
        m_rec = ls%m + lr%m * share
        m_rot = lr%m * (1.0_wp - share)
        w = -(m_rot + fraction * m_rec) * (b - pc)
      end associate
      omega = abs(deck%omega(1))
      kg = unit_symbol("kg", lang)
      m = unit_symbol("m", lang)
      n_unit = unit_symbol("N", lang)
      if (lang == lang_ru) then
        call rep%put("частичное уравновешивание"// &
          " кривошипно-ползунного механизма: масса кривошипа, "// &
          "вращающаяся масса "//short_number(m_rot)//" "//kg//" и доля"// &
            " "//short_number(fraction)// &
          " возвратно-поступательно движущейся массы"// &
            " "//short_number(m_rec)//" "//kg// &
          " на радиусе кривошипа "//short_number(r)//" "//m)
        call rep%put("  (масса шатуна разнесена в две точки:"// &
          " доля "//short_number(share)//" в шарнире ползуна)")
        call rep%put("  сила инерции первого порядка (первая"// &
          " гармоника, m_rec*r*omega1^2 = "// &
          short_number(m_rec * r * omega**2)//" "//n_unit//" при omega1 = "//short_number(omega)//" "// &
          unit_symbol("rad/s", lang)//"): вдоль направляющей"// &
            " "//short_number(m_rec * r * omega**2)//" "//n_unit// &
          " до уравновешивания,"// &
            " "//short_number((1.0_wp - fraction) * m_rec * r * omega**2)//" "//n_unit// &
          " после; поперек направляющей 0 до,"// &
            " "//short_number(fraction * m_rec * r * omega**2)//" "//n_unit//" после")
        call rep%put("  сила инерции второго порядка (вторая"// &
          " гармоника, m_rec*r*omega1^2*r/l): "// &
          short_number(m_rec * r * omega**2 * r / l)//" "//n_unit//" вдоль"// &
            " направляющей, не меняется "// &
          "(противовес на кривошипе вращается с угловой"// &
            " скоростью omega1)")
      else
        call rep%put("partial balance of the slider-crank: the crank's own mass, the rotating mass "// &
          short_number(m_rot)//" kg and "//short_number(fraction)//" of the reciprocating mass "// &
          short_number(m_rec)//" kg at the crank radius "//short_number(r)//" m")
        call rep%put("  (rod as two masses: "//short_number(share)//" of it at the slider's pin)")
        call rep%put("  primary component (first harmonic, m_rec*r*omega1^2 = "// &
          short_number(m_rec * r * omega**2)//" N at omega1 = "//short_number(omega)//" rad/s): along the "// &
          "guide "//short_number(m_rec * r * omega**2)//" N before, "// &
          short_number((1.0_wp - fraction) * m_rec * r * omega**2)//" N after; across the guide 0 before, "// &
          short_number(fraction * m_rec * r * omega**2)//" N after")
        call rep%put("  secondary component (second harmonic, m_rec*r*omega1^2*r/l): "// &
          short_number(m_rec * r * omega**2 * r / l)//" N along the guide, unchanged (a crank counterweight "// &
          "turns at omega1 only)")
      end if
    end subroutine partial
  end subroutine linkage_balance

  !> The links turning about a pivot on the frame (a turning pair with the frame): their
  !> pivots, m (global).
  pure subroutine pivots(mech, pivot, pivoted)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(out) :: pivot(:, :)
    logical, intent(out) :: pivoted(:)
    integer :: k
    pivot = 0.0_wp
    pivoted = .false.
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        if (pr%kind /= pair_r .or. min(pr%a, pr%b) /= 0 .or. max(pr%a, pr%b) == 0) cycle
        pivoted(max(pr%a, pr%b)) = .true.
        pivot(:, max(pr%a, pr%b)) = pr%at
      end associate
    end do
  end subroutine pivots

  !> Full static balance: the first moments of the links pivoted on the frame.
  pure subroutine full_balance(deck, pivot, lang, w_new, carries, report, error)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), intent(in) :: pivot(:, :)
    integer, intent(in) :: lang
    !> New first moments about the pivots (reference orientation), kg*m.
    real(wp), intent(inout) :: w_new(:, :)
    !> In: the links pivoted on the frame; out: those that carry a counterweight.
    logical, intent(inout) :: carries(:)
    type(text_buffer_t), intent(inout) :: report
    type(error_t), allocatable, intent(out) :: error
    real(wp), allocatable :: poses(:, :), a(:, :), b(:), x(:), moment(:, :)
    integer, allocatable :: piv(:)
    integer :: nl, ns, i, k, j, nu
    real(wp) :: mean(2), unbalanced, residual, r(2), turn
    call sample_poses(deck, poses, error)
    if (allocated(error)) return
    nl = size(carries)
    ns = size(poses, 2)
    allocate (moment(2, ns), source=0.0_wp)
    do k = 1, ns
      do i = 1, nl
        moment(:, k) = moment(:, k) + deck%mech%links(i)%m * point_position(deck%mech, poses(:, k), i, &
          deck%mech%links(i)%s)
      end do
    end do
    mean = sum(moment, dim=2) / real(ns, wp)
    unbalanced = 0.0_wp
    do k = 1, ns
      unbalanced = max(unbalanced, norm2(moment(:, k) - mean))
    end do
    allocate (piv(0))
    do i = 1, nl
      if (.not. carries(i)) cycle
      turn = maxval(abs(cos(poses(3 * i, :)) - cos(poses(3 * i, 1)))) + maxval(abs(sin(poses(3 * i, :)) - &
        sin(poses(3 * i, 1))))
      if (turn >= 1.0e-9_wp) piv = [piv, i]
    end do
    carries = .false.
    if (.not. unbalanced > 0.0_wp) then
      call report%put(in_language("full balance: the total centre of mass does not move (nothing to balance)", &
        "полное статическое уравновешивание: общий"// &
          " центр масс неподвижен (уравновешивать нечего)", lang))
      return
    end if
    nu = 2 * size(piv) + 2
    allocate (a(2 * ns, nu), b(2 * ns), x(nu))
    do k = 1, ns
      b(2 * k - 1:2 * k) = -moment(:, k)
      do j = 1, size(piv)
        i = piv(j)
        associate (l => deck%mech%links(i))
          b(2 * k - 1:2 * k) = b(2 * k - 1:2 * k) + l%m * rotate(l%s - pivot(:, i), poses(3 * i, k))
          a(2 * k - 1:2 * k, 2 * j - 1) = rotate([1.0_wp, 0.0_wp], poses(3 * i, k))
          a(2 * k - 1:2 * k, 2 * j) = rotate([0.0_wp, 1.0_wp], poses(3 * i, k))
        end associate
      end do
      a(2 * k - 1:2 * k, nu - 1) = [-1.0_wp, 0.0_wp]
      a(2 * k - 1:2 * k, nu) = [0.0_wp, -1.0_wp]
    end do
    call least_squares(a, b, x, error)
    if (allocated(error)) then
      call fatal_error(error, exit_geometry, "full balance: the counterweights are not determined (the links "// &
        "pivoted on the frame move together); balance the crank alone (--method crank)")
      return
    end if
    residual = 0.0_wp
    do k = 1, ns
      r = -moment(:, k)
      do j = 1, size(piv)
        associate (l => deck%mech%links(piv(j)))
          r = r + rotate(l%m * (l%s - pivot(:, piv(j))) - x(2 * j - 1:2 * j), poses(3 * piv(j), k))
        end associate
      end do
      residual = max(residual, norm2(r + x(nu - 1:nu)))
    end do
    if (residual > balance_rel * unbalanced) then
      call fatal_error(error, exit_geometry, "full balance is impossible: counterweights on the links pivoted on "// &
        "the frame leave "//short_number(residual / unbalanced * 100.0_wp)//" % of the centre of mass's travel "// &
        "(a link whose origin moves, such as a slider on the frame, cannot be balanced by them); "// &
        "use --method partial [--fraction F] (a slider-crank) or --method crank")
      return
    end if
    do j = 1, size(piv)
      w_new(:, piv(j)) = x(2 * j - 1:2 * j)
      carries(piv(j)) = .true.
    end do
    ! the constant C is the total first moment but for the counterweights' own m_c P
    do j = 1, size(piv)
      x(nu - 1:nu) = x(nu - 1:nu) + (mass_after(piv(j)) - deck%mech%links(piv(j))%m) * pivot(:, piv(j))
    end do
    call report%put(in_language("full balance (linearly independent vectors): counterweights on the "// &
      int_str(size(piv))//" links pivoted on the frame; the total centre of mass stays at (", &
      "полное статическое уравновешивание (метод"// &
        " линейно независимых векторов): противовесы на "// &
      int_str(size(piv))//" звеньях, вращающихся вокруг"// &
        " неподвижных осей; общий центр масс неподвижен в точке (", &
      lang)//short_number(x(nu - 1) / total_mass())//", "//short_number(x(nu) / total_mass())//") "// &
      unit_symbol("m", lang))
  contains
    !> A pivoted link's mass with its counterweight, kg.
    pure real(wp) function mass_after(q)
      integer, intent(in) :: q
      real(wp) :: extra(2)
      associate (l => deck%mech%links(q))
        mass_after = l%m
        extra = w_new(:, q) - l%m * (l%s - pivot(:, q))
        if (norm2(extra) > 0.0_wp) mass_after = l%m + norm2(extra) / link_radius(deck%mech, q, pivot(:, q))
      end associate
    end function mass_after
    !> The moving links' mass after balancing, kg.
    pure real(wp) function total_mass()
      integer :: q
      total_mass = 0.0_wp
      do q = 1, nl
        if (carries(q)) then
          total_mass = total_mass + mass_after(q)
        else
          total_mass = total_mass + deck%mech%links(q)%m
        end if
      end do
    end function total_mass
  end subroutine full_balance

  !> The poses (3n x samples) over a turn of the first drive from its first step, every 5 deg,
  !> by continuation from the reference position; over the deck's steps when the linkage does
  !> not go round, or with several drives or a sliding first drive.
  pure subroutine sample_poses(deck, poses, error)
    type(linkage_deck_t), intent(in) :: deck
    real(wp), allocatable, intent(out) :: poses(:, :)
    type(error_t), allocatable, intent(out) :: error
    type(linkage_work_t) :: work
    real(wp) :: q(3 * size(deck%mech%links)), dq(size(deck%mech%drives)), dv(size(deck%mech%drives)), &
      da(size(deck%mech%drives)), from(size(deck%mech%drives)), first
    integer :: k
    logical :: turn
    turn = size(deck%mech%drives) == 1 .and. deck%mech%pairs(deck%mech%drives(1)%pair)%kind == pair_r
    if (turn) then
      allocate (poses(size(q), sample_count))
      call start(q, from)
      call linkage_drive_values(deck, 1, dq, dv, da)
      first = dq(1)
      do k = 1, sample_count
        dq(1) = first + 5.0_wp * real(k - 1, wp) * deg_to_rad
        call linkage_assemble(deck%mech, from, dq, q, work, error)
        if (allocated(error)) exit
        from = dq
        poses(:, k) = q
      end do
      if (.not. allocated(error)) return
      deallocate (error, poses)
    end if
    allocate (poses(size(q), deck%n))
    call start(q, from)
    do k = 1, deck%n
      call linkage_drive_values(deck, k, dq, dv, da)
      call linkage_assemble(deck%mech, from, dq, q, work, error)
      if (allocated(error)) return
      from = dq
      poses(:, k) = q
    end do
  contains
    pure subroutine start(q0, from0)
      real(wp), intent(out) :: q0(:), from0(:)
      integer :: dd
      q0 = linkage_reference_pose(deck%mech)
      do dd = 1, size(from0)
        from0(dd) = deck%mech%drives(dd)%q_ref
      end do
    end subroutine start
  end subroutine sample_poses

  !> The assignments of link i's counterweight for its new first moment w about its pivot p
  !> (reference orientation): a point mass at the link's radius on the side w - m*(s - p)
  !> points to.
  pure subroutine add_counterweight(deck, i, p, w, method, lang, overrides, report)
    type(linkage_deck_t), intent(in) :: deck
    integer, intent(in) :: i
    real(wp), intent(in) :: p(2), w(2)
    integer, intent(in) :: method, lang
    type(override_t), allocatable, intent(inout) :: overrides(:)
    type(text_buffer_t), intent(inout) :: report
    real(wp) :: dw(2), radius, mc, c(2), m_new, s_new(2), j_new, angle
    character(len=:), allocatable :: prefix, note
    associate (l => deck%mech%links(i))
      dw = w - l%m * (l%s - p)
      if (norm2(dw) <= 1.0e-15_wp * max(norm2(w), norm2(l%m * (l%s - p)))) return
      radius = link_radius(deck%mech, i, p)
      mc = norm2(dw) / radius
      c = p + radius * dw / norm2(dw)
      angle = atan2(dw(2), dw(1)) * rad_to_deg
      m_new = l%m + mc
      s_new = p + w / m_new
      j_new = l%j + l%m * sum((l%s - s_new)**2) + mc * sum((c - s_new)**2)
      prefix = "link("//int_str(i)//")%"
      if (lang == lang_ru) then
        note = "противовес на звене "//int_str(l%id)//":"// &
          " "//short_number(mc)//" "//unit_symbol("kg", lang)// &
          " на радиусе r = "//short_number(radius)//" "//unit_symbol("m", lang)//","// &
            " "//short_number(angle)//" "// &
          unit_symbol("deg", lang)//" от оси вращения в исходном"// &
            " положении (m*r = "//short_number(mc * radius)// &
          " "//unit_symbol("kg", lang)//"·"//unit_symbol("m", lang)//")"
      else
        note = "counterweight on link "//int_str(l%id)//": "//short_number(mc)//" kg at r = "// &
          short_number(radius)//" m, "//short_number(angle)//" deg from its pivot at the reference position "// &
          "(m*r = "//short_number(mc * radius)//" kg*m)"
      end if
      call append_override(overrides, prefix//"m", full_number(m_new)//"   ! "//note//";"// &
        " kinetostat balance --method "// &
        trim(method_names(method)))
      call append_override(overrides, prefix//"j", full_number(j_new))
      call append_override(overrides, prefix//"s", full_number(s_new(1))//", "//full_number(s_new(2)))
      call report%put(note)
      call report%put("  "//prefix//"m "//short_number(l%m)//" -> "//short_number(m_new)//" "// &
        unit_symbol("kg", lang)//", "//prefix//"j "//short_number(l%j)//" -> "//short_number(j_new)//" "// &
        unit_symbol("kg*m^2", lang)//in_language(", centre of mass (", ", центр масс (", lang)// &
        short_number(l%s(1))//", "//short_number(l%s(2))//") -> ("//short_number(s_new(1))//", "// &
        short_number(s_new(2))//") "//unit_symbol("m", lang)//in_language(" at the reference position", &
        " в исходном положении", lang))
    end associate
  end subroutine add_counterweight

  !> Where link i carries a counterweight: at the distance of its farthest joint from its
  !> pivot p, m (0.1 m for a link without another joint).
  pure real(wp) function link_radius(mech, i, p) result(radius)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: i
    real(wp), intent(in) :: p(2)
    integer :: k
    radius = 0.0_wp
    do k = 1, size(mech%pairs)
      if (mech%pairs(k)%a == i .or. mech%pairs(k)%b == i) radius = max(radius, norm2(mech%pairs(k)%at - p))
    end do
    if (.not. radius > 0.0_wp) radius = 0.1_wp
  end function link_radius

end module kinetostat_linkage_balance
