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
  use kinetostat_labels, only: in_language
  use kinetostat_override, only: override_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_counterweights, only: method_crank => balance_crank, method_partial => balance_partial, &
    method_names => balance_method_names, fit_full_balance, report_full_balance, report_partial_balance, &
    counterweight_note, add_counterweight_assignments
  use kinetostat_linkage, only: linkage_t, linkage_work_t, pair_r, pair_p, linkage_reference_pose, linkage_assemble, &
    point_position
  use kinetostat_linkage_deck, only: linkage_deck_t, linkage_drive_values
  implicit none
  private
  public :: linkage_balance

  !> Positions of the sample turn (every 5 deg).
  integer, parameter :: sample_count = 72

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
      call report_partial_balance(rep, lang, "", "", m_rot, m_rec, fraction, share, r, l, omega)
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
    real(wp), allocatable :: poses(:, :), x(:), moment(:, :), theta(:, :), own(:, :), mass(:)
    integer, allocatable :: piv(:)
    integer :: nl, ns, i, k, j, nu
    real(wp) :: turn
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
    allocate (piv(0))
    do i = 1, nl
      if (.not. carries(i)) cycle
      turn = maxval(abs(cos(poses(3 * i, :)) - cos(poses(3 * i, 1)))) + maxval(abs(sin(poses(3 * i, :)) - &
        sin(poses(3 * i, 1))))
      if (turn >= 1.0e-9_wp) piv = [piv, i]
    end do
    carries = .false.
    theta = poses(3:3 * nl:3, :)
    own = reshape([(deck%mech%links(i)%s - pivot(:, i), i = 1, nl)], [2, nl])
    mass = deck%mech%links%m
    call fit_full_balance(moment, theta, mass, own, piv, lang, report, w_new, carries, x, error)
    if (allocated(error) .or. .not. allocated(x)) return
    nu = size(x)
    ! the constant C is the total first moment but for the counterweights' own m_c P
    do j = 1, size(piv)
      x(nu - 1:nu) = x(nu - 1:nu) + (mass_after(piv(j)) - deck%mech%links(piv(j))%m) * pivot(:, piv(j))
    end do
    call report_full_balance(report, lang, size(piv), x(nu - 1:nu) / total_mass())
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
      note = counterweight_note(lang, l%id, mc, radius, angle, "from its pivot at the reference position", &
        "от оси вращения в исходном положении")
      call add_counterweight_assignments(overrides, report, lang, method, note, &
        prefix//"m", prefix//"j", prefix//"s", l%m, m_new, l%j, j_new, l%s, s_new, s_new, &
        " at the reference position", " в исходном положении")
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
