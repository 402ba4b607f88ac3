!> Cell types and their geometry: Code_Aster's names, node counts and node order, the
!> reference element of each type and its Lagrange shape functions (the isoparametric map
!> from reference coordinates to a cell), as Code_Aster defines them (R3.01.01, the
!> catalogue `mesh_types.py` and the reference elements of `elrfvf` / `elrfdf`):
!>
!> | type  | nodes | reference element and node order                                   |
!> |-------|-------|--------------------------------------------------------------------|
!> | POI1  | 1     | a point                                                            |
!> | SEG2  | 2     | xi = -1, +1                                                        |
!> | SEG3  | 3     | xi = -1, +1, then the middle 0                                     |
!> | TRIA3 | 3     | (0,0), (1,0), (0,1)                                                |
!> | TRIA6 | 6     | TRIA3's corners, then the middles of sides 1-2, 2-3, 3-1           |
!> | QUAD4 | 4     | (-1,-1), (1,-1), (1,1), (-1,1)                                     |
!> | QUAD8 | 8     | QUAD4's corners, then the middles of sides 1-2, 2-3, 3-4, 4-1      |
!> | QUAD9 | 9     | QUAD8's nodes, then the centre (0,0)                               |
!>
!> Corner (vertex) nodes always come first. MED, Gmsh and VTK number the nodes of these
!> types the same way (Code_Aster permutes only 3D types when it reads MED).
!> The type numbers below are parasol's own; the order of CELL_TYPE_ORDER is Code_Aster's
!> catalogue order, in which its MED reader numbers cells type by type.
module mesh_cell_shapes
    use kinds, only: dp, i4
    implicit none
    private

    !> Cell types (Code_Aster names). Index into the CELL_TYPE_* tables.
    integer(i4), parameter, public :: CELL_POI1 = 1, CELL_SEG2 = 2, CELL_TRIA3 = 3, &
        CELL_QUAD4 = 4, CELL_SEG3 = 5, CELL_TRIA6 = 6, CELL_QUAD8 = 7, CELL_QUAD9 = 8, &
        N_CELL_TYPES = 8
    character(len=5), parameter, public :: CELL_TYPE_NAMES(N_CELL_TYPES) = &
        ['POI1 ', 'SEG2 ', 'TRIA3', 'QUAD4', 'SEG3 ', 'TRIA6', 'QUAD8', 'QUAD9']
    !> Nodes per cell.
    integer(i4), parameter, public :: CELL_TYPE_NODES(N_CELL_TYPES) = [1, 2, 3, 4, 3, 6, 8, 9]
    !> Corner (vertex) nodes per cell: the first ones of the cell (Code_Aster's NOEU_S).
    integer(i4), parameter, public :: CELL_TYPE_CORNERS(N_CELL_TYPES) = &
        [1, 2, 3, 4, 2, 3, 4, 4]
    !> Topological dimension (0 point, 1 line, 2 surface).
    integer(i4), parameter, public :: CELL_TYPE_DIM(N_CELL_TYPES) = [0, 1, 2, 2, 1, 2, 2, 2]
    !> The linear type on the same corners (QUAD8 -> QUAD4 ...).
    integer(i4), parameter, public :: CELL_TYPE_LINEAR(N_CELL_TYPES) = &
        [CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, &
         CELL_QUAD4]
    !> Code_Aster's catalogue order of the types (POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4,
    !> QUAD8, QUAD9): its MED reader numbers the cells of a file type by type in this order.
    integer(i4), parameter, public :: CELL_TYPE_ORDER(N_CELL_TYPES) = [CELL_POI1, CELL_SEG2, &
        CELL_SEG3, CELL_TRIA3, CELL_TRIA6, CELL_QUAD4, CELL_QUAD8, CELL_QUAD9]
    !> Most nodes of any cell type.
    integer(i4), parameter, public :: MAX_CELL_NODES = 9

    public :: cell_type_of_name, cell_shape, cell_reference_nodes, cell_type_is_quadratic, &
        cell_geometric_measure, cell_edge_count, cell_edge_nodes

contains

    !> CELL_* number of a Code_Aster cell type name (case as written: upper case), 0 if
    !> parasol has no such type.
    pure integer(i4) function cell_type_of_name(name) result(ctype)
        character(len=*), intent(in) :: name
        integer(i4) :: t
        ctype = 0
        do t = 1, N_CELL_TYPES
            if (trim(CELL_TYPE_NAMES(t)) == trim(adjustl(name))) ctype = t
        end do
    end function cell_type_of_name

    !> True for SEG3, TRIA6, QUAD8, QUAD9 (nodes beyond the corners).
    elemental logical function cell_type_is_quadratic(ctype)
        integer(i4), intent(in) :: ctype
        cell_type_is_quadratic = CELL_TYPE_NODES(ctype) > CELL_TYPE_CORNERS(ctype)
    end function cell_type_is_quadratic

    !> Reference coordinates of the nodes of a cell type (see the module header).
    !>  ctype : in, CELL_*
    !>  xi    : out, xi(1:2, 1:CELL_TYPE_NODES(ctype)) (unused entries 0; lines use xi(1, :))
    pure subroutine cell_reference_nodes(ctype, xi)
        integer(i4), intent(in) :: ctype
        real(dp), intent(out) :: xi(2, MAX_CELL_NODES)
        real(dp), parameter :: QX(9) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, &
            0.0_dp, -1.0_dp, 0.0_dp]
        real(dp), parameter :: QY(9) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, &
            1.0_dp, 0.0_dp, 0.0_dp]
        real(dp), parameter :: TX(6) = [0.0_dp, 1.0_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp]
        real(dp), parameter :: TY(6) = [0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.5_dp, 0.5_dp]
        xi = 0.0_dp
        select case (ctype)
        case (CELL_SEG2, CELL_SEG3)
            xi(1, 1:3) = [-1.0_dp, 1.0_dp, 0.0_dp]
        case (CELL_TRIA3, CELL_TRIA6)
            xi(1, 1:6) = TX
            xi(2, 1:6) = TY
        case (CELL_QUAD4, CELL_QUAD8, CELL_QUAD9)
            xi(1, :) = QX
            xi(2, :) = QY
        end select
        if (CELL_TYPE_NODES(ctype) < MAX_CELL_NODES) xi(:, CELL_TYPE_NODES(ctype) + 1:) = 0.0_dp
    end subroutine cell_reference_nodes

    !> Shape functions of a cell type and their derivatives at reference point (xi, eta)
    !> (Code_Aster's elrfvf / elrfdf; eta unused for lines).
    !>  ctype   : in, CELL_*
    !>  xi, eta : in, reference coordinates
    !>  n       : out, n(1:nn) shape functions (nn = CELL_TYPE_NODES(ctype))
    !>  dn      : out, dn(1:2, 1:nn): d/dxi, d/deta (lines: dn(1, :) only; POI1: 0)
    pure subroutine cell_shape(ctype, xi, eta, n, dn)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xi, eta
        real(dp), intent(out) :: n(:), dn(:, :)
        n = 0.0_dp
        dn = 0.0_dp
        select case (ctype)
        case (CELL_POI1)
            n(1) = 1.0_dp
        case (CELL_SEG2)
            n(1:2) = [1.0_dp - xi, 1.0_dp + xi] / 2.0_dp
            dn(1, 1:2) = [-0.5_dp, 0.5_dp]
        case (CELL_SEG3)
            ! Lagrange on -1, +1, 0
            n(1:3) = [lagrange3(1, xi), lagrange3(3, xi), lagrange3(2, xi)]
            dn(1, 1:3) = [dlagrange3(1, xi), dlagrange3(3, xi), dlagrange3(2, xi)]
        case (CELL_TRIA3)
            n(1:3) = [1.0_dp - xi - eta, xi, eta]
            dn(1, 1:3) = [-1.0_dp, 1.0_dp, 0.0_dp]
            dn(2, 1:3) = [-1.0_dp, 0.0_dp, 1.0_dp]
        case (CELL_TRIA6)
            call tria6_shape(xi, eta, n, dn)
        case (CELL_QUAD4)
            call quad4_shape(xi, eta, n, dn)
        case (CELL_QUAD8)
            call quad8_shape(xi, eta, n, dn)
        case (CELL_QUAD9)
            call quad9_shape(xi, eta, n, dn)
        end select
    end subroutine cell_shape

    ! 1D quadratic Lagrange polynomials on the nodes -1 (k = 1), 0 (k = 2), +1 (k = 3).
    pure real(dp) function lagrange3(k, x) result(v)
        integer, intent(in) :: k
        real(dp), intent(in) :: x
        select case (k)
        case (1)
            v = 0.5_dp * x * (x - 1.0_dp)
        case (2)
            v = (1.0_dp - x) * (1.0_dp + x)
        case default
            v = 0.5_dp * x * (x + 1.0_dp)
        end select
    end function lagrange3

    pure real(dp) function dlagrange3(k, x) result(v)
        integer, intent(in) :: k
        real(dp), intent(in) :: x
        select case (k)
        case (1)
            v = x - 0.5_dp
        case (2)
            v = -2.0_dp * x
        case default
            v = x + 0.5_dp
        end select
    end function dlagrange3

    pure subroutine tria6_shape(x, y, n, dn)
        real(dp), intent(in) :: x, y
        real(dp), intent(out) :: n(:), dn(:, :)
        real(dp) :: l
        l = 1.0_dp - x - y
        n(1:6) = [l * (2.0_dp * l - 1.0_dp), x * (2.0_dp * x - 1.0_dp), &
                  y * (2.0_dp * y - 1.0_dp), 4.0_dp * x * l, 4.0_dp * x * y, 4.0_dp * y * l]
        dn(1, 1:6) = [1.0_dp - 4.0_dp * l, 4.0_dp * x - 1.0_dp, 0.0_dp, 4.0_dp * (l - x), &
                      4.0_dp * y, -4.0_dp * y]
        dn(2, 1:6) = [1.0_dp - 4.0_dp * l, 0.0_dp, 4.0_dp * y - 1.0_dp, -4.0_dp * x, &
                      4.0_dp * x, 4.0_dp * (l - y)]
    end subroutine tria6_shape

    pure subroutine quad4_shape(x, y, n, dn)
        real(dp), intent(in) :: x, y
        real(dp), intent(out) :: n(:), dn(:, :)
        real(dp), parameter :: XN(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: YN(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        integer :: i
        do i = 1, 4
            n(i) = 0.25_dp * (1.0_dp + XN(i) * x) * (1.0_dp + YN(i) * y)
            dn(1, i) = 0.25_dp * XN(i) * (1.0_dp + YN(i) * y)
            dn(2, i) = 0.25_dp * YN(i) * (1.0_dp + XN(i) * x)
        end do
    end subroutine quad4_shape

    ! 8-node serendipity quadrilateral (Code_Aster's QU8).
    pure subroutine quad8_shape(x, y, n, dn)
        real(dp), intent(in) :: x, y
        real(dp), intent(out) :: n(:), dn(:, :)
        real(dp), parameter :: XN(8) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, 1.0_dp, &
            0.0_dp, -1.0_dp]
        real(dp), parameter :: YN(8) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 0.0_dp, &
            1.0_dp, 0.0_dp]
        integer :: i
        real(dp) :: a, b
        do i = 1, 4
            a = 1.0_dp + XN(i) * x
            b = 1.0_dp + YN(i) * y
            n(i) = 0.25_dp * a * b * (XN(i) * x + YN(i) * y - 1.0_dp)
            dn(1, i) = 0.25_dp * XN(i) * b * (2.0_dp * XN(i) * x + YN(i) * y)
            dn(2, i) = 0.25_dp * YN(i) * a * (XN(i) * x + 2.0_dp * YN(i) * y)
        end do
        do i = 5, 7, 2          ! middles of the sides eta = -1, +1
            b = 1.0_dp + YN(i) * y
            n(i) = 0.5_dp * (1.0_dp - x * x) * b
            dn(1, i) = -x * b
            dn(2, i) = 0.5_dp * YN(i) * (1.0_dp - x * x)
        end do
        do i = 6, 8, 2          ! middles of the sides xi = +1, -1
            a = 1.0_dp + XN(i) * x
            n(i) = 0.5_dp * a * (1.0_dp - y * y)
            dn(1, i) = 0.5_dp * XN(i) * (1.0_dp - y * y)
            dn(2, i) = -y * a
        end do
    end subroutine quad8_shape

    ! 9-node Lagrange quadrilateral: products of the 1D quadratic polynomials.
    pure subroutine quad9_shape(x, y, n, dn)
        real(dp), intent(in) :: x, y
        real(dp), intent(out) :: n(:), dn(:, :)
        ! 1D node index (1: -1, 2: 0, 3: +1) of each node along xi and eta
        integer, parameter :: IX(9) = [1, 3, 3, 1, 2, 3, 2, 1, 2]
        integer, parameter :: IY(9) = [1, 1, 3, 3, 1, 2, 3, 2, 2]
        integer :: i
        do i = 1, 9
            n(i) = lagrange3(IX(i), x) * lagrange3(IY(i), y)
            dn(1, i) = dlagrange3(IX(i), x) * lagrange3(IY(i), y)
            dn(2, i) = lagrange3(IX(i), x) * dlagrange3(IY(i), y)
        end do
    end subroutine quad9_shape

    !> Length, area or 0 of a cell of type `ctype` with node coordinates x: the integral of
    !> |dx/dxi| (lines) or |x_xi x x_eta| (surfaces, in 3D too) over the reference element,
    !> by Gauss rules exact for straight-sided plane cells of every type (3 points on lines,
    !> 3x3 on quadrilaterals, 6 points on triangles) and accurate for curved or warped ones.
    !>  ctype : in, CELL_*
    !>  x     : in, x(3, CELL_TYPE_NODES(ctype)) node coordinates
    pure real(dp) function cell_geometric_measure(ctype, x) result(measure)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: x(:, :)
        real(dp) :: pts(2, 9), w(9), n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), t1(3), t2(3)
        integer(i4) :: g, np, nn
        measure = 0.0_dp
        nn = CELL_TYPE_NODES(ctype)
        select case (CELL_TYPE_DIM(ctype))
        case (1)
            np = 3
            pts(1, 1:3) = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
            w(1:3) = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
        case (2)
            if (CELL_TYPE_CORNERS(ctype) == 3) then
                call triangle_rule6(pts, w)
                np = 6
            else
                call square_rule9(pts, w)
                np = 9
            end if
        case default
            return
        end select
        do g = 1, np
            call cell_shape(ctype, pts(1, g), pts(2, g), n(1:nn), dn(:, 1:nn))
            t1 = matmul(x(:, 1:nn), dn(1, 1:nn))
            if (CELL_TYPE_DIM(ctype) == 1) then
                measure = measure + norm2(t1) * w(g)
            else
                t2 = matmul(x(:, 1:nn), dn(2, 1:nn))
                measure = measure + norm2([t1(2) * t2(3) - t1(3) * t2(2), &
                    t1(3) * t2(1) - t1(1) * t2(3), t1(1) * t2(2) - t1(2) * t2(1)]) * w(g)
            end if
        end do
    end function cell_geometric_measure

    ! Strang-Fix 6-point rule on the reference triangle (degree 4; weights sum to 1/2).
    pure subroutine triangle_rule6(pts, w)
        real(dp), intent(out) :: pts(2, 9), w(9)
        real(dp), parameter :: A = 0.44594849091596488632_dp, B = 0.091576213509770743460_dp
        real(dp), parameter :: WA = 0.11169079483900573285_dp, WB = 0.054975871827660933820_dp
        pts = 0.0_dp
        w = 0.0_dp
        pts(:, 1) = [B, B]
        pts(:, 2) = [1.0_dp - 2.0_dp * B, B]
        pts(:, 3) = [B, 1.0_dp - 2.0_dp * B]
        pts(:, 4) = [A, 1.0_dp - 2.0_dp * A]
        pts(:, 5) = [A, A]
        pts(:, 6) = [1.0_dp - 2.0_dp * A, A]
        w(1:3) = WB
        w(4:6) = WA
    end subroutine triangle_rule6

    ! 3x3 Gauss-Legendre on [-1,1]^2.
    pure subroutine square_rule9(pts, w)
        real(dp), intent(out) :: pts(2, 9), w(9)
        real(dp) :: x1(3), w1(3)
        integer :: i, j
        x1 = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
        w1 = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
        do j = 1, 3
            do i = 1, 3
                pts(:, i + 3 * (j - 1)) = [x1(i), x1(j)]
                w(i + 3 * (j - 1)) = w1(i) * w1(j)
            end do
        end do
    end subroutine square_rule9

    !> Number of edges of a surface cell type (3 or 4; 0 for points and lines).
    pure integer(i4) function cell_edge_count(ctype) result(n)
        integer(i4), intent(in) :: ctype
        n = 0
        if (CELL_TYPE_DIM(ctype) == 2) n = CELL_TYPE_CORNERS(ctype)
    end function cell_edge_count

    !> Local node indices of edge `k` of a surface cell, in the cell's turning order: the
    !> two corners k, k+1 and, for quadratic cells, the middle node (SEG3 order: ends,
    !> then middle). n_edge_nodes = 2 or 3.
    pure subroutine cell_edge_nodes(ctype, k, nodes, n_edge_nodes)
        integer(i4), intent(in) :: ctype, k
        integer(i4), intent(out) :: nodes(3), n_edge_nodes
        integer(i4) :: nc
        nc = CELL_TYPE_CORNERS(ctype)
        nodes = 0
        nodes(1) = k
        nodes(2) = mod(k, nc) + 1
        n_edge_nodes = 2
        if (cell_type_is_quadratic(ctype)) then
            nodes(3) = nc + k
            n_edge_nodes = 3
        end if
    end subroutine cell_edge_nodes

end module mesh_cell_shapes
