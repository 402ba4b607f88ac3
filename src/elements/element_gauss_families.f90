!> Code_Aster's integration families: for each element formulation and cell type, which
!> Gauss scheme each family (location) uses, the points of each scheme in Code_Aster's
!> order, and the Gauss -> node (ELNO) extrapolation matrix, so that an ELGA field's
!> POINT = n and an ELNO field mean here what they mean in Code_Aster.
!>
!> Families (Code_Aster's element catalogues, catalo/cataelem/Elements/*.py, `gauss=`):
!>
!> | formulation            | cell  | RIGI | MASS | FPG1 | NOEU | MTGA |
!> |------------------------|-------|------|------|------|------|------|
!> | plane (D_PLAN, C_PLAN) | TRIA3 | FPG1 | FPG3 | FPG1 | NOEU | FPG1 |
!> |                        | TRIA6 | FPG3 | FPG6 | FPG1 | NOEU | FPG3 |
!> |                        | QUAD4 | FPG4 | FPG4 | FPG1 | NOEU | FPG4 |
!> |                        | QUAD8 | FPG9 | FPG9 | FPG1 | NOEU | FPG9 |
!> |                        | QUAD9 | FPG9 | FPG9 | FPG1 | NOEU | FPG9 |
!> | plane edge (skin)      | SEG2  | FPG2 |      |      |      |      |
!> |                        | SEG3  | FPG4 |      |      |      |      |
!> | plate (DKT, DKQ)       | TRIA3 | FPG3 | FPG4 | FPG1 | NOEU |      |
!> |                        | QUAD4 | FPG4 | FPG9 | FPG1 | NOEU |      |
!> | discrete (DIS_*)       | POI1, SEG2 | NOEU |  | FPG1 |      |      |
!>
!> Schemes (Code_Aster's elraga; reference elements of mesh_cell_shapes):
!>  - FPG1: the centroid of the reference nodes, weight = reference measure;
!>  - lines: FPG2 (+1/sqrt3, -1/sqrt3: the first point is nearer node 2), FPG3 (-sqrt(3/5),
!>    0, +sqrt(3/5)), FPG4 (a, -a, b, -b with a, b the inner and outer Gauss-Legendre
!>    abscissae);
!>  - triangles: FPG3 (1/6,1/6) (2/3,1/6) (1/6,2/3); FPG4 (1/5,1/5) (3/5,1/5) (1/5,3/5)
!>    (1/3,1/3) with weights 25/96 and -27/96; FPG6 (Strang-Fix, degree 4): (b,b)
!>    (1-2b,b) (b,1-2b) then (a,1-2a) (a,a) (1-2a,a);
!>  - quadrangles: FPG4 (-g,-g) (g,-g) (g,g) (-g,g), g = 1/sqrt3; FPG9 the four corners
!>    (+-c, +-c) in that turn, the four side middles (0,-c) (c,0) (0,c) (-c,0), the centre,
!>    c = sqrt(3/5);
!>  - NOEU: the reference nodes (weight: reference measure / nodes); NOEU_S its corners.
!>
!> ELNO (Code_Aster's inmat4 / inmat5 / inmat6, R3.06.03): one point: its value at every
!> node; NOEU: the identity; otherwise the corner values are the least-squares fit of the
!> linear cell's shape functions to the Gauss values (exact extrapolation when the points
!> are as many as the corners), and a side-middle node takes the mean of its two corners,
!> the QUAD9 centre the mean of the four.
module element_gauss_families
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_INTERNAL
    use mesh_cell_shapes, only: CELL_POI1, CELL_SEG2, CELL_SEG3, CELL_TRIA3, CELL_TRIA6, &
        CELL_QUAD4, CELL_QUAD8, CELL_QUAD9, CELL_TYPE_NAMES, CELL_TYPE_NODES, &
        CELL_TYPE_CORNERS, CELL_TYPE_DIM, CELL_TYPE_LINEAR, MAX_CELL_NODES, cell_shape, &
        cell_reference_nodes
    implicit none
    private

    !> Element formulations (the families depend on it, not only on the cell type).
    integer(i4), parameter, public :: FORMULATION_PLANE = 1, FORMULATION_PLANE_EDGE = 2, &
        FORMULATION_PLATE = 3, FORMULATION_DISCRETE = 4
    !> Most points of any scheme here (FPG9).
    integer(i4), parameter, public :: MAX_GAUSS_POINTS = 9

    !> The points of one scheme on one reference element.
    type, public :: gauss_rule_t
        character(len=8) :: scheme = ''                !< FPG4, NOEU, ...
        integer(i4) :: cell_type = 0                   !< CELL_* of the reference element
        integer(i4) :: n = 0                           !< number of points
        real(dp) :: xi(2, MAX_GAUSS_POINTS) = 0.0_dp   !< reference coordinates (lines: xi(1,:))
        real(dp) :: w(MAX_GAUSS_POINTS) = 0.0_dp       !< weights
    end type gauss_rule_t

    public :: gauss_scheme, gauss_family, family_scheme_name, gauss_to_nodes, &
        gauss_point_positions

contains

    !> The scheme a formulation's family (location) uses on a cell type (table above);
    !> '' when the element has no such family.
    !>  formulation : in, FORMULATION_*
    !>  ctype       : in, CELL_*
    !>  location    : in, RIGI, MASS, FPG1, NOEU, NOEU_S or MTGA
    pure function family_scheme_name(formulation, ctype, location) result(scheme)
        integer(i4), intent(in) :: formulation, ctype
        character(len=*), intent(in) :: location
        character(len=:), allocatable :: scheme
        scheme = ''
        select case (formulation)
        case (FORMULATION_PLANE)
            if (CELL_TYPE_DIM(ctype) /= 2) return
            select case (location)
            case ('RIGI', 'MTGA')
                scheme = plane_rigi(ctype)
            case ('MASS')
                scheme = plane_mass(ctype)
            case ('FPG1', 'NOEU', 'NOEU_S')
                scheme = location
            end select
        case (FORMULATION_PLANE_EDGE)
            if (location /= 'RIGI') return
            if (ctype == CELL_SEG2) scheme = 'FPG2'
            if (ctype == CELL_SEG3) scheme = 'FPG4'
        case (FORMULATION_PLATE)
            if (ctype /= CELL_TRIA3 .and. ctype /= CELL_QUAD4) return
            select case (location)
            case ('RIGI')
                scheme = trim(merge('FPG3', 'FPG4', ctype == CELL_TRIA3))
            case ('MASS')
                scheme = trim(merge('FPG4', 'FPG9', ctype == CELL_TRIA3))
            case ('FPG1', 'NOEU')
                scheme = location
            end select
        case (FORMULATION_DISCRETE)
            if (ctype /= CELL_POI1 .and. ctype /= CELL_SEG2) return
            if (location == 'RIGI') scheme = 'NOEU'
            if (location == 'FPG1') scheme = 'FPG1'
        end select
    contains
        pure function plane_rigi(t) result(name)
            integer(i4), intent(in) :: t
            character(len=:), allocatable :: name
            select case (t)
            case (CELL_TRIA3)
                name = 'FPG1'
            case (CELL_TRIA6)
                name = 'FPG3'
            case (CELL_QUAD4)
                name = 'FPG4'
            case default
                name = 'FPG9'
            end select
        end function plane_rigi
        pure function plane_mass(t) result(name)
            integer(i4), intent(in) :: t
            character(len=:), allocatable :: name
            select case (t)
            case (CELL_TRIA3)
                name = 'FPG3'
            case (CELL_TRIA6)
                name = 'FPG6'
            case (CELL_QUAD4)
                name = 'FPG4'
            case default
                name = 'FPG9'
            end select
        end function plane_mass
    end function family_scheme_name

    !> The points of a formulation's family on a cell type (family_scheme_name, then
    !> gauss_scheme).
    !>  st : out, STATUS_INTERNAL when the element has no such family
    subroutine gauss_family(formulation, ctype, location, rule, st)
        integer(i4), intent(in) :: formulation, ctype
        character(len=*), intent(in) :: location
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: scheme
        scheme = family_scheme_name(formulation, ctype, location)
        if (len(scheme) == 0) then
            call set_error(st, STATUS_INTERNAL, 'no Gauss family ' // location // ' on ' // &
                trim(CELL_TYPE_NAMES(ctype)) // ' for this element')
            return
        end if
        call gauss_scheme(ctype, scheme, rule, st)
    end subroutine gauss_family

    !> The points and weights of a Code_Aster scheme on the reference element of `ctype`.
    !>  ctype  : in, CELL_* (the scheme is the one of its reference element: TRIA6 takes
    !>           the triangle's, QUAD8 the quadrangle's)
    !>  scheme : in, FPG1, FPG2, FPG3, FPG4, FPG6, FPG9, NOEU or NOEU_S
    !>  rule   : out
    !>  st     : out, STATUS_INTERNAL for a scheme this reference element lacks here
    subroutine gauss_scheme(ctype, scheme, rule, st)
        integer(i4), intent(in) :: ctype
        character(len=*), intent(in) :: scheme
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        real(dp) :: nodes(2, MAX_CELL_NODES)
        integer(i4) :: nn
        rule%scheme = scheme
        rule%cell_type = ctype
        call cell_reference_nodes(ctype, nodes)
        select case (scheme)
        case ('NOEU', 'NOEU_S')
            nn = CELL_TYPE_NODES(ctype)
            if (scheme == 'NOEU_S') nn = CELL_TYPE_CORNERS(ctype)
            rule%n = nn
            rule%xi(:, 1:nn) = nodes(:, 1:nn)
            rule%w(1:nn) = reference_measure(ctype) / real(nn, dp)
        case ('FPG1')
            nn = CELL_TYPE_NODES(ctype)
            rule%n = 1
            rule%xi(:, 1) = sum(nodes(:, 1:nn), dim=2) / real(nn, dp)
            rule%w(1) = reference_measure(ctype)
        case default
            select case (CELL_TYPE_DIM(ctype))
            case (1)
                call line_scheme(scheme, rule)
            case (2)
                if (CELL_TYPE_CORNERS(ctype) == 3) then
                    call triangle_scheme(scheme, rule)
                else
                    call quadrangle_scheme(scheme, rule)
                end if
            end select
        end select
        if (rule%n == 0) call set_error(st, STATUS_INTERNAL, 'no Gauss scheme ' // scheme // &
            ' on ' // trim(CELL_TYPE_NAMES(ctype)))
    end subroutine gauss_scheme

    pure real(dp) function reference_measure(ctype) result(v)
        integer(i4), intent(in) :: ctype
        select case (CELL_TYPE_DIM(ctype))
        case (0)
            v = 1.0_dp
        case (1)
            v = 2.0_dp
        case default
            v = merge(0.5_dp, 4.0_dp, CELL_TYPE_CORNERS(ctype) == 3)
        end select
    end function reference_measure

    pure subroutine line_scheme(scheme, rule)
        character(len=*), intent(in) :: scheme
        type(gauss_rule_t), intent(inout) :: rule
        real(dp) :: a, b
        select case (scheme)
        case ('FPG2')
            rule%n = 2
            rule%xi(1, 1:2) = [1.0_dp, -1.0_dp] / sqrt(3.0_dp)
            rule%w(1:2) = 1.0_dp
        case ('FPG3')
            rule%n = 3
            rule%xi(1, 1:3) = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
            rule%w(1:3) = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
        case ('FPG4')
            rule%n = 4
            a = sqrt(3.0_dp / 7.0_dp - 2.0_dp / 7.0_dp * sqrt(6.0_dp / 5.0_dp))
            b = sqrt(3.0_dp / 7.0_dp + 2.0_dp / 7.0_dp * sqrt(6.0_dp / 5.0_dp))
            rule%xi(1, 1:4) = [a, -a, b, -b]
            rule%w(1:2) = (18.0_dp + sqrt(30.0_dp)) / 36.0_dp
            rule%w(3:4) = (18.0_dp - sqrt(30.0_dp)) / 36.0_dp
        end select
    end subroutine line_scheme

    pure subroutine triangle_scheme(scheme, rule)
        character(len=*), intent(in) :: scheme
        type(gauss_rule_t), intent(inout) :: rule
        ! Strang-Fix 6-point rule (Code_Aster's FPG6), full precision
        real(dp), parameter :: A = 0.44594849091596488632_dp, B = 0.091576213509770743460_dp
        real(dp), parameter :: WA = 0.11169079483900573285_dp, WB = 0.054975871827660933820_dp
        select case (scheme)
        case ('FPG3')
            rule%n = 3
            rule%xi(:, 1) = [1.0_dp, 1.0_dp] / 6.0_dp
            rule%xi(:, 2) = [2.0_dp / 3.0_dp, 1.0_dp / 6.0_dp]
            rule%xi(:, 3) = [1.0_dp / 6.0_dp, 2.0_dp / 3.0_dp]
            rule%w(1:3) = 1.0_dp / 6.0_dp
        case ('FPG4')
            rule%n = 4
            rule%xi(:, 1) = [0.2_dp, 0.2_dp]
            rule%xi(:, 2) = [0.6_dp, 0.2_dp]
            rule%xi(:, 3) = [0.2_dp, 0.6_dp]
            rule%xi(:, 4) = [1.0_dp, 1.0_dp] / 3.0_dp
            rule%w(1:3) = 25.0_dp / 96.0_dp
            rule%w(4) = -27.0_dp / 96.0_dp
        case ('FPG6')
            rule%n = 6
            rule%xi(:, 1) = [B, B]
            rule%xi(:, 2) = [1.0_dp - 2.0_dp * B, B]
            rule%xi(:, 3) = [B, 1.0_dp - 2.0_dp * B]
            rule%xi(:, 4) = [A, 1.0_dp - 2.0_dp * A]
            rule%xi(:, 5) = [A, A]
            rule%xi(:, 6) = [1.0_dp - 2.0_dp * A, A]
            rule%w(1:3) = WB
            rule%w(4:6) = WA
        end select
    end subroutine triangle_scheme

    pure subroutine quadrangle_scheme(scheme, rule)
        character(len=*), intent(in) :: scheme
        type(gauss_rule_t), intent(inout) :: rule
        real(dp) :: g, c
        select case (scheme)
        case ('FPG4')
            rule%n = 4
            g = 1.0_dp / sqrt(3.0_dp)
            rule%xi(1, 1:4) = [-g, g, g, -g]
            rule%xi(2, 1:4) = [-g, -g, g, g]
            rule%w(1:4) = 1.0_dp
        case ('FPG9')
            rule%n = 9
            c = sqrt(0.6_dp)
            rule%xi(1, 1:9) = [-c, c, c, -c, 0.0_dp, c, 0.0_dp, -c, 0.0_dp]
            rule%xi(2, 1:9) = [-c, -c, c, c, -c, 0.0_dp, c, 0.0_dp, 0.0_dp]
            rule%w(1:4) = 25.0_dp / 81.0_dp
            rule%w(5:8) = 40.0_dp / 81.0_dp
            rule%w(9) = 64.0_dp / 81.0_dp
        end select
    end subroutine quadrangle_scheme

    !> Gauss -> node extrapolation of a scheme on its cell type, as Code_Aster (module
    !> header): the value at node i is sum_g m(i, g) v_g.
    !>  rule : in, the scheme (rule%cell_type its cell)
    !>  m    : out, m(1:nn, 1:rule%n), nn = CELL_TYPE_NODES(rule%cell_type)
    !>  st   : out, STATUS_INTERNAL when the points cannot fix the corner values (fewer
    !>         points than corners, other than one point)
    subroutine gauss_to_nodes(rule, m, st)
        type(gauss_rule_t), intent(in) :: rule
        real(dp), intent(out) :: m(:, :)
        type(status_t), intent(out) :: st
        integer(i4) :: ctype, nn, nc, g, i, j, info
        real(dp) :: a(4, 4), p(4, MAX_GAUSS_POINTS), n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES)
        real(dp) :: corners(4, MAX_GAUSS_POINTS)
        integer(i4) :: ipiv(4)
        ctype = rule%cell_type
        nn = CELL_TYPE_NODES(ctype)
        nc = CELL_TYPE_CORNERS(ctype)
        m = 0.0_dp
        if (rule%n == 1) then
            m(1:nn, 1) = 1.0_dp
            return
        end if
        if (rule%scheme == 'NOEU') then
            do i = 1, nn
                m(i, i) = 1.0_dp
            end do
            return
        end if
        if (rule%n < nc) then
            call set_error(st, STATUS_INTERNAL, 'ELNO: ' // trim(rule%scheme) // ' on ' // &
                trim(CELL_TYPE_NAMES(ctype)) // ' has fewer points than corners')
            return
        end if
        if (rule%scheme == 'NOEU_S') then
            corners = 0.0_dp
            do i = 1, nc
                corners(i, i) = 1.0_dp
            end do
        else
            ! normal equations of the least-squares fit: A c = P v, A = sum N N^T, P(:, g) = N(g)
            a = 0.0_dp
            do g = 1, rule%n
                call cell_shape(CELL_TYPE_LINEAR(ctype), rule%xi(1, g), rule%xi(2, g), &
                    n(1:nc), dn(:, 1:nc))
                p(1:nc, g) = n(1:nc)
                do j = 1, nc
                    a(1:nc, j) = a(1:nc, j) + n(1:nc) * n(j)
                end do
            end do
            corners(1:nc, 1:rule%n) = p(1:nc, 1:rule%n)
            call solve_small(nc, a, rule%n, corners, ipiv, info)
            if (info /= 0) then
                call set_error(st, STATUS_INTERNAL, 'ELNO: the points of ' // &
                    trim(rule%scheme) // ' on ' // trim(CELL_TYPE_NAMES(ctype)) // &
                    ' cannot fix the corner values')
                return
            end if
        end if
        m(1:nc, 1:rule%n) = corners(1:nc, 1:rule%n)
        call middle_nodes(ctype, rule%n, m)
    end subroutine gauss_to_nodes

    ! Side middles: the mean of their two corners; the QUAD9 centre: of the four.
    pure subroutine middle_nodes(ctype, npg, m)
        integer(i4), intent(in) :: ctype, npg
        real(dp), intent(inout) :: m(:, :)
        integer(i4) :: nc, k
        nc = CELL_TYPE_CORNERS(ctype)
        select case (ctype)
        case (CELL_SEG3)
            m(3, 1:npg) = 0.5_dp * (m(1, 1:npg) + m(2, 1:npg))
        case (CELL_TRIA6, CELL_QUAD8, CELL_QUAD9)
            do k = 1, nc
                m(nc + k, 1:npg) = 0.5_dp * (m(k, 1:npg) + m(mod(k, nc) + 1, 1:npg))
            end do
            if (ctype == CELL_QUAD9) m(9, 1:npg) = 0.25_dp * sum(m(1:4, 1:npg), dim=1)
        end select
    end subroutine middle_nodes

    ! Gaussian elimination with partial pivoting of a(1:n,1:n) x = b(1:n, 1:nrhs), n <= 4
    ! (the corner systems of the ELNO fit); b is overwritten with x. info > 0: singular.
    pure subroutine solve_small(n, a, nrhs, b, ipiv, info)
        integer(i4), intent(in) :: n, nrhs
        real(dp), intent(inout) :: a(4, 4), b(4, MAX_GAUSS_POINTS)
        integer(i4), intent(out) :: ipiv(4), info
        integer(i4) :: k, i, p
        real(dp) :: f, row(4), rb(MAX_GAUSS_POINTS), scale
        info = 0
        scale = maxval(abs(a(1:n, 1:n)))
        do k = 1, n
            p = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
            ipiv(k) = p
            if (.not. abs(a(p, k)) > 1.0e3_dp * epsilon(1.0_dp) * scale) then
                info = k
                return
            end if
            if (p /= k) then
                row(1:n) = a(k, 1:n)
                a(k, 1:n) = a(p, 1:n)
                a(p, 1:n) = row(1:n)
                rb(1:nrhs) = b(k, 1:nrhs)
                b(k, 1:nrhs) = b(p, 1:nrhs)
                b(p, 1:nrhs) = rb(1:nrhs)
            end if
            do i = k + 1, n
                f = a(i, k) / a(k, k)
                a(i, k:n) = a(i, k:n) - f * a(k, k:n)
                b(i, 1:nrhs) = b(i, 1:nrhs) - f * b(k, 1:nrhs)
            end do
        end do
        do k = n, 1, -1
            b(k, 1:nrhs) = (b(k, 1:nrhs) - matmul(a(k, k + 1:n), b(k + 1:n, 1:nrhs))) / a(k, k)
        end do
    end subroutine solve_small

    !> Positions of the points of `rule` on a cell (the isoparametric map of its type).
    !>  x   : in, x(3, nn) node coordinates
    !>  pos : out, pos(3, rule%n)
    pure subroutine gauss_point_positions(rule, x, pos)
        type(gauss_rule_t), intent(in) :: rule
        real(dp), intent(in) :: x(:, :)
        real(dp), intent(out) :: pos(:, :)
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES)
        integer(i4) :: g, nn
        nn = CELL_TYPE_NODES(rule%cell_type)
        do g = 1, rule%n
            call cell_shape(rule%cell_type, rule%xi(1, g), rule%xi(2, g), n(1:nn), dn(:, 1:nn))
            pos(:, g) = matmul(x(:, 1:nn), n(1:nn))
        end do
    end subroutine gauss_point_positions

end module element_gauss_families
