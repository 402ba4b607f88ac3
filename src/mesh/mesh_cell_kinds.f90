!> What the mesh commands need to know of a cell type beyond its node count: its dimension,
!> its vertices (the first nodes, Code_Aster's "sommets"), its mid-edge nodes ("milieux")
!> and its centre nodes ("centre"), in Code_Aster's node order (vertices first, then one
!> node per edge, then face and volume centres: SEG3, TRIA6/7, QUAD8/9).
!>
!> Decided from the type's name (POI, SEG, TRIA, QUAD, TETRA, PENTA, PYRAM, HEXA), so cell
!> types added to mesh_types later are covered without a second table to keep in step.
module mesh_cell_kinds
    use kinds, only: i4
    use mesh_types, only: CELL_TYPE_NAMES, CELL_TYPE_NODES
    implicit none
    private

    !> Node roles, for CREA_GROUP_NO/CRIT_NOEUD (TOUS, SOMMET, MILIEU, CENTRE).
    integer(i4), parameter, public :: ROLE_ALL = 0, ROLE_VERTEX = 1, ROLE_MID_EDGE = 2, &
        ROLE_CENTRE = 3

    public :: cell_dimension, cell_vertex_count, cell_edge_count, role_range, &
        type_matches_filter

contains

    !> 0 (POI), 1 (SEG), 2 (TRIA, QUAD) or 3 (volumes) for cell type `ctype`.
    pure integer(i4) function cell_dimension(ctype) result(d)
        integer(i4), intent(in) :: ctype
        select case (family(ctype))
        case ('POI')
            d = 0
        case ('SEG')
            d = 1
        case ('TRIA', 'QUAD')
            d = 2
        case default
            d = 3
        end select
    end function cell_dimension

    !> Number of vertices (corner nodes) of a cell of type `ctype`.
    pure integer(i4) function cell_vertex_count(ctype) result(n)
        integer(i4), intent(in) :: ctype
        select case (family(ctype))
        case ('POI')
            n = 1
        case ('SEG')
            n = 2
        case ('TRIA')
            n = 3
        case ('QUAD', 'TETRA')
            n = 4
        case ('PYRAM')
            n = 5
        case ('PENTA')
            n = 6
        case default
            n = 8
        end select
        n = min(n, CELL_TYPE_NODES(ctype))
    end function cell_vertex_count

    !> Number of edges of a cell of type `ctype` (0 for POI1).
    pure integer(i4) function cell_edge_count(ctype) result(n)
        integer(i4), intent(in) :: ctype
        select case (family(ctype))
        case ('POI')
            n = 0
        case ('SEG')
            n = 1
        case ('TRIA')
            n = 3
        case ('QUAD')
            n = 4
        case ('TETRA')
            n = 6
        case ('PYRAM')
            n = 8
        case ('PENTA')
            n = 9
        case default
            n = 12
        end select
    end function cell_edge_count

    !> The positions first..last (1-based, in the cell's node list) of the nodes of `role`
    !> in a cell of type `ctype`; first > last when it has none (a linear cell has no
    !> mid-edge node).
    pure subroutine role_range(ctype, role, first, last)
        integer(i4), intent(in) :: ctype, role
        integer(i4), intent(out) :: first, last
        integer(i4) :: nv, ne, nn
        nv = cell_vertex_count(ctype)
        ne = cell_edge_count(ctype)
        nn = CELL_TYPE_NODES(ctype)
        select case (role)
        case (ROLE_VERTEX)
            first = 1
            last = nv
        case (ROLE_MID_EDGE)
            first = nv + 1
            last = min(nv + ne, nn)
            if (family(ctype) == 'SEG') last = min(nv + 1, nn)
        case (ROLE_CENTRE)
            first = nv + ne + 1
            if (family(ctype) == 'SEG') first = nn + 1   ! SEG3's third node is a mid node
            last = nn
        case default
            first = 1
            last = nn
        end select
    end subroutine role_range

    !> True when cell type `ctype` passes CREA_GROUP_MA/TYPE_MAILLE `filter`: TOUT, a
    !> dimension (1D, 2D, 3D) or a type name.
    pure logical function type_matches_filter(ctype, filter) result(ok)
        integer(i4), intent(in) :: ctype
        character(len=*), intent(in) :: filter
        select case (filter)
        case ('TOUT')
            ok = .true.
        case ('1D')
            ok = cell_dimension(ctype) == 1
        case ('2D')
            ok = cell_dimension(ctype) == 2
        case ('3D')
            ok = cell_dimension(ctype) == 3
        case default
            ok = trim(CELL_TYPE_NAMES(ctype)) == filter
        end select
    end function type_matches_filter

    ! 'POI', 'SEG', 'TRIA', ... : the type name without its node count.
    pure function family(ctype) result(name)
        integer(i4), intent(in) :: ctype
        character(len=:), allocatable :: name
        integer :: k
        name = trim(CELL_TYPE_NAMES(ctype))
        k = scan(name, '0123456789')
        if (k > 1) name = name(1:k - 1)
    end function family

end module mesh_cell_kinds
