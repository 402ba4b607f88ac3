!> How many points an element field has on a cell (field_types), and which points they are:
!> ELGA the Gauss points of the element's stiffness family (Code_Aster's RIGI,
!> element_gauss_families: DKQ FPG4, DKT FPG3; plane TRIA3 FPG1, TRIA6 FPG3, QUAD4 FPG4,
!> QUAD8 and QUAD9 FPG9; discrete springs RIGI=NOEU, their nodes), ELNO the cell's nodes,
!> ELEM and CART one. Cells without an element, and the plane elements' load edges, have
!> none.
module field_layout
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    use mesh_types, only: CELL_POI1, CELL_SEG2, CELL_TYPE_NODES, CELL_TYPE_NAMES
    use model_types, only: ELEM_NONE, is_plate, is_plane_solid, is_discrete
    use element_gauss_families, only: gauss_rule_t, gauss_family, family_scheme_name, &
        FORMULATION_PLANE, FORMULATION_PLATE, FORMULATION_DISCRETE
    use field_types, only: FIELD_ELGA, FIELD_ELNO, FIELD_ELEM, FIELD_CART
    implicit none
    private

    public :: element_point_count, gauss_point_count, element_formulation, element_points

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
        if (element_formulation(kind) == 0) return
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

    !> The formulation (element_gauss_families FORMULATION_*) of element `kind`, 0 for none
    !> (no element, a load edge).
    elemental integer(i4) function element_formulation(kind) result(f)
        integer(i4), intent(in) :: kind
        f = 0
        if (kind == ELEM_NONE) return
        if (is_plate(kind)) f = FORMULATION_PLATE
        if (is_plane_solid(kind)) f = FORMULATION_PLANE
        if (is_discrete(kind)) f = FORMULATION_DISCRETE
    end function element_formulation

    !> Gauss points of the RIGI family of element `kind` on `cell_type` (module header).
    pure integer(i4) function gauss_point_count(kind, cell_type) result(n)
        integer(i4), intent(in) :: kind, cell_type
        character(len=:), allocatable :: scheme
        n = 0
        if (is_discrete(kind)) then
            if (cell_type == CELL_SEG2) n = 2
            if (cell_type == CELL_POI1) n = 1
            return
        end if
        if (element_formulation(kind) == 0) return
        scheme = family_scheme_name(element_formulation(kind), cell_type, 'RIGI')
        select case (scheme)
        case ('FPG1')
            n = 1
        case ('FPG3')
            n = 3
        case ('FPG4')
            n = 4
        case ('FPG6')
            n = 6
        case ('FPG9')
            n = 9
        end select
    end function gauss_point_count

    !> The reference points of an element field with `n_points` points on a cell: the
    !> element family with that many points, RIGI first, then MASS, FPG1 and the nodes.
    !>  st : STATUS_MODEL_ERROR when no family of the element has that many points
    subroutine element_points(kind, cell_type, n_points, rule, st)
        integer(i4), intent(in) :: kind, cell_type, n_points
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        character(len=4), parameter :: FAMILIES(4) = ['RIGI', 'MASS', 'FPG1', 'NOEU']
        type(status_t) :: tried
        integer(i4) :: k
        do k = 1, size(FAMILIES)
            if (len(family_scheme_name(element_formulation(kind), cell_type, &
                FAMILIES(k))) == 0) cycle
            call gauss_family(element_formulation(kind), cell_type, FAMILIES(k), rule, tried)
            if (tried%ok() .and. rule%n == n_points) return
        end do
        call set_error(st, STATUS_MODEL_ERROR, 'no family of points of this element has ' // &
            to_text(n_points) // ' points on a ' // trim(CELL_TYPE_NAMES(cell_type)))
    end subroutine element_points

end module field_layout
