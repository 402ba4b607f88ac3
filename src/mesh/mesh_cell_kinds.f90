!> What the mesh commands need to know of a cell's nodes beyond mesh_cell_shapes' tables:
!> which of them are vertices (Code_Aster's "sommets"), mid-edge nodes ("milieux") or centre
!> nodes ("centre") in Code_Aster's node order (vertices first, then one node per edge,
!> then the face centre: SEG3, TRIA6, QUAD8, QUAD9), and whether a type passes a
!> TYPE_MAILLE filter.
module mesh_cell_kinds
    use kinds, only: i4
    use mesh_cell_shapes, only: CELL_TYPE_NAMES, CELL_TYPE_NODES, CELL_TYPE_CORNERS, &
        CELL_TYPE_DIM, cell_edge_count
    implicit none
    private

    !> Node roles, for CREA_GROUP_NO/CRIT_NOEUD (TOUS, SOMMET, MILIEU, CENTRE).
    integer(i4), parameter, public :: ROLE_ALL = 0, ROLE_VERTEX = 1, ROLE_MID_EDGE = 2, &
        ROLE_CENTRE = 3

    public :: cell_dimension, role_range, type_matches_filter

contains

    !> 0 (POI), 1 (SEG), 2 (TRIA, QUAD) for cell type `ctype`.
    pure integer(i4) function cell_dimension(ctype) result(d)
        integer(i4), intent(in) :: ctype
        d = CELL_TYPE_DIM(ctype)
    end function cell_dimension

    !> The positions first..last (1-based, in the cell's node list) of the nodes of `role`
    !> in a cell of type `ctype`; first > last when it has none (a linear cell has no
    !> mid-edge node). A line's one edge is the line itself: SEG3's third node is its middle.
    pure subroutine role_range(ctype, role, first, last)
        integer(i4), intent(in) :: ctype, role
        integer(i4), intent(out) :: first, last
        integer(i4) :: nv, ne, nn
        nv = CELL_TYPE_CORNERS(ctype)
        ne = cell_edge_count(ctype)
        if (CELL_TYPE_DIM(ctype) == 1) ne = 1
        nn = CELL_TYPE_NODES(ctype)
        select case (role)
        case (ROLE_VERTEX)
            first = 1
            last = nv
        case (ROLE_MID_EDGE)
            first = nv + 1
            last = min(nv + ne, nn)
        case (ROLE_CENTRE)
            first = nv + ne + 1
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
            ok = CELL_TYPE_DIM(ctype) == 1
        case ('2D')
            ok = CELL_TYPE_DIM(ctype) == 2
        case ('3D')
            ok = CELL_TYPE_DIM(ctype) == 3
        case default
            ok = trim(CELL_TYPE_NAMES(ctype)) == filter
        end select
    end function type_matches_filter

end module mesh_cell_kinds
