!> How many points an element field has on a cell (field_types): ELGA the Gauss points of
!> the element's stiffness family (Code_Aster's RIGI, catalo/cataelem/Elements: DKQ FPG4,
!> DKT FPG3; plane QUAD4 FPG4, TRIA3 FPG1, TRIA6 FPG3, QUAD8 and QUAD9 FPG9; discrete
!> springs RIGI=NOEU, their nodes), ELNO the cell's nodes, ELEM and CART one. Cells without
!> an element, and the plane elements' load edges, have none.
module field_layout
    use kinds, only: i4
    use mesh_types, only: CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_TRIA6, &
        CELL_QUAD8, CELL_QUAD9, CELL_TYPE_NODES
    use model_types, only: ELEM_NONE, is_plate, is_plane_solid, is_discrete
    use field_types, only: FIELD_ELGA, FIELD_ELNO, FIELD_ELEM, FIELD_CART
    implicit none
    private

    public :: element_point_count, gauss_point_count

contains

    !> Points of a field of `location` on a cell of type `cell_type` carrying element `kind`
    !> (0: none). CART fields exist on every cell (a carte is by zone, not by element).
    pure integer(i4) function element_point_count(kind, cell_type, location) result(n)
        integer(i4), intent(in) :: kind, cell_type, location
        n = 0
        if (location == FIELD_CART) then
            n = 1
            return
        end if
        if (kind == ELEM_NONE) return
        if (.not. (is_plate(kind) .or. is_plane_solid(kind) .or. is_discrete(kind))) return
        select case (location)
        case (FIELD_ELGA)
            n = gauss_point_count(kind, cell_type)
        case (FIELD_ELNO)
            if (cell_type >= 1 .and. cell_type <= size(CELL_TYPE_NODES)) &
                n = CELL_TYPE_NODES(cell_type)
        case (FIELD_ELEM)
            n = 1
        end select
    end function element_point_count

    !> Gauss points of the RIGI family of element `kind` on `cell_type` (module header).
    pure integer(i4) function gauss_point_count(kind, cell_type) result(n)
        integer(i4), intent(in) :: kind, cell_type
        n = 0
        if (is_discrete(kind)) then
            if (cell_type == CELL_SEG2) n = 2
            if (cell_type == CELL_POI1) n = 1
        else if (is_plate(kind)) then
            if (cell_type == CELL_QUAD4) n = 4
            if (cell_type == CELL_TRIA3) n = 3
        else if (is_plane_solid(kind)) then
            select case (cell_type)
            case (CELL_TRIA3)
                n = 1
            case (CELL_QUAD4)
                n = 4
            case (CELL_TRIA6)
                n = 3
            case (CELL_QUAD8, CELL_QUAD9)
                n = 9
            end select
        end if
    end function gauss_point_count

end module field_layout
