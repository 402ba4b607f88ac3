!> The model (AFFE_MODELE): which finite element, if any, each mesh cell carries.
!>
!> An element kind combines the modelisation and the cell type (Code_Aster's "type
!> element"): 'DKT' on QUAD4 is the DKQ quadrilateral, on TRIA3 the DKT triangle, on SEG2
!> a load-carrying plate edge (Code_Aster's MEBODKT: no stiffness, FORCE_ARETE);
!> 'D_PLAN'/'C_PLAN' on TRIA3, TRIA6, QUAD4, QUAD8, QUAD9 are plane strain/stress solids
!> (Code_Aster's MEDPTR3 ... MECPQU9) and on SEG2, SEG3 load-carrying edges (no stiffness:
!> FORCE_CONTOUR, PRES_REP); 'DIS_T' and '2D_DIS_T' are translational discrete springs on
!> SEG2 or POI1, 'DIS_TR' and '2D_DIS_TR' the same with the rotations (DRX, DRY, DRZ; in
!> 2D DRZ).
module model_types
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_upper
    use mesh_types, only: mesh_t, cell_label, CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, &
        CELL_TYPE_NAMES, CELL_TYPE_ORDER, N_CELL_TYPES
    implicit none
    private

    !> Element kinds (per cell). ELEM_NONE: the cell carries no element.
    integer(i4), parameter, public :: ELEM_NONE = 0, ELEM_DKQ = 1, ELEM_DKT = 2, &
        ELEM_D_PLAN_QUAD4 = 3, ELEM_C_PLAN_QUAD4 = 4, ELEM_D_PLAN_SEG2 = 5, &
        ELEM_C_PLAN_SEG2 = 6, ELEM_DIS_T_SEG2 = 7, ELEM_DIS_T_POI1 = 8, &
        ELEM_2D_DIS_T_SEG2 = 9, ELEM_2D_DIS_T_POI1 = 10, ELEM_D_PLAN_TRIA3 = 11, &
        ELEM_C_PLAN_TRIA3 = 12, ELEM_D_PLAN_TRIA6 = 13, ELEM_C_PLAN_TRIA6 = 14, &
        ELEM_D_PLAN_QUAD8 = 15, ELEM_C_PLAN_QUAD8 = 16, ELEM_D_PLAN_QUAD9 = 17, &
        ELEM_C_PLAN_QUAD9 = 18, ELEM_D_PLAN_SEG3 = 19, ELEM_C_PLAN_SEG3 = 20, &
        ELEM_DIS_TR_SEG2 = 21, ELEM_DIS_TR_POI1 = 22, ELEM_2D_DIS_TR_SEG2 = 23, &
        ELEM_2D_DIS_TR_POI1 = 24, ELEM_DKT_SEG2 = 25, N_ELEMENT_KINDS = 25
    !> Names of the element kinds (for the .mess model summary).
    character(len=14), parameter, public :: ELEMENT_NAMES(0:N_ELEMENT_KINDS) = [ &
        'NONE          ', 'DKQ           ', 'DKT           ', 'D_PLAN_QUAD4  ', &
        'C_PLAN_QUAD4  ', 'D_PLAN_SEG2   ', 'C_PLAN_SEG2   ', 'DIS_T_SEG2    ', &
        'DIS_T_POI1    ', '2D_DIS_T_SEG2 ', '2D_DIS_T_POI1 ', 'D_PLAN_TRIA3  ', &
        'C_PLAN_TRIA3  ', 'D_PLAN_TRIA6  ', 'C_PLAN_TRIA6  ', 'D_PLAN_QUAD8  ', &
        'C_PLAN_QUAD8  ', 'D_PLAN_QUAD9  ', 'C_PLAN_QUAD9  ', 'D_PLAN_SEG3   ', &
        'C_PLAN_SEG3   ', 'DIS_TR_SEG2   ', 'DIS_TR_POI1   ', '2D_DIS_TR_SEG2', &
        '2D_DIS_TR_POI1', 'DKT_SEG2      ']
    !> Modelisations accepted by AFFE_MODELE.
    character(len=9), parameter, public :: MODELISATIONS(7) = ['DKT      ', 'D_PLAN   ', &
        'C_PLAN   ', 'DIS_T    ', '2D_DIS_T ', 'DIS_TR   ', '2D_DIS_TR']

    !> The plane kinds by cell type (D_PLAN, C_PLAN), 0 where the type has none.
    integer(i4), parameter :: D_PLAN_KINDS(N_CELL_TYPES) = [0, ELEM_D_PLAN_SEG2, &
        ELEM_D_PLAN_TRIA3, ELEM_D_PLAN_QUAD4, ELEM_D_PLAN_SEG3, ELEM_D_PLAN_TRIA6, &
        ELEM_D_PLAN_QUAD8, ELEM_D_PLAN_QUAD9]
    integer(i4), parameter :: C_PLAN_KINDS(N_CELL_TYPES) = [0, ELEM_C_PLAN_SEG2, &
        ELEM_C_PLAN_TRIA3, ELEM_C_PLAN_QUAD4, ELEM_C_PLAN_SEG3, ELEM_C_PLAN_TRIA6, &
        ELEM_C_PLAN_QUAD8, ELEM_C_PLAN_QUAD9]

    !> Finite element per cell of one mesh.
    type, public :: model_t
        integer(i4) :: n_cells = 0
        integer(i4), allocatable :: element(:)     !< ELEM_* per cell
    end type model_t

    public :: model_init, assign_modelisation, element_for, is_plate, is_plane_solid, &
        is_plane_edge, is_plate_edge, is_load_edge, is_plane_strain, is_discrete, is_discrete_2d, is_discrete_rotational, &
        n_modelled_cells

contains

    !> A model of `mesh` with no element on any cell.
    subroutine model_init(model, mesh)
        type(model_t), intent(out) :: model
        type(mesh_t), intent(in) :: mesh
        model%n_cells = mesh%n_cells
        allocate (model%element(mesh%n_cells), source=ELEM_NONE)
    end subroutine model_init

    !> Element kind of `modelisation` on a cell of type `cell_type`, ELEM_NONE if the pair
    !> does not exist, -1 if the modelisation is unknown.
    pure integer(i4) function element_for(modelisation, cell_type) result(kind)
        character(len=*), intent(in) :: modelisation
        integer(i4), intent(in) :: cell_type
        kind = ELEM_NONE
        select case (modelisation)
        case ('DKT')
            if (cell_type == CELL_QUAD4) kind = ELEM_DKQ
            if (cell_type == CELL_TRIA3) kind = ELEM_DKT
            if (cell_type == CELL_SEG2) kind = ELEM_DKT_SEG2
        case ('D_PLAN')
            if (cell_type >= 1 .and. cell_type <= N_CELL_TYPES) kind = D_PLAN_KINDS(cell_type)
        case ('C_PLAN')
            if (cell_type >= 1 .and. cell_type <= N_CELL_TYPES) kind = C_PLAN_KINDS(cell_type)
        case ('DIS_T')
            if (cell_type == CELL_SEG2) kind = ELEM_DIS_T_SEG2
            if (cell_type == CELL_POI1) kind = ELEM_DIS_T_POI1
        case ('2D_DIS_T')
            if (cell_type == CELL_SEG2) kind = ELEM_2D_DIS_T_SEG2
            if (cell_type == CELL_POI1) kind = ELEM_2D_DIS_T_POI1
        case ('DIS_TR')
            if (cell_type == CELL_SEG2) kind = ELEM_DIS_TR_SEG2
            if (cell_type == CELL_POI1) kind = ELEM_DIS_TR_POI1
        case ('2D_DIS_TR')
            if (cell_type == CELL_SEG2) kind = ELEM_2D_DIS_TR_SEG2
            if (cell_type == CELL_POI1) kind = ELEM_2D_DIS_TR_POI1
        case default
            kind = -1
        end select
    end function element_for

    !> Gives `cells` the element of `modelisation` (later assignments override earlier ones).
    !>  model, mesh   : inout model / in its mesh
    !>  cells         : in, cell numbers
    !>  modelisation  : in, one of MODELISATIONS (case-insensitive)
    !>  st            : out, STATUS_MODEL_ERROR for an unknown modelisation or a cell whose
    !>                  type has no element of that modelisation (naming cell and group)
    !>  group         : in, optional GROUP_MA name the cells came from (messages)
    !>  skip_incompatible : in, optional; .true. for TOUT='OUI': cells of other types are
    !>                  left as they are (an error only if no cell at all fits)
    subroutine assign_modelisation(model, mesh, cells, modelisation, st, group, &
                                   skip_incompatible)
        type(model_t), intent(inout) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        character(len=*), intent(in) :: modelisation
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: group
        logical, intent(in), optional :: skip_incompatible
        integer(i4) :: i, c, kind, n_fit
        logical :: skip
        character(len=:), allocatable :: name
        name = to_upper(trim(modelisation))
        skip = .false.
        if (present(skip_incompatible)) skip = skip_incompatible
        if (element_for(name, CELL_QUAD4) < 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'unknown MODELISATION ' // name // &
                ' (DKT, D_PLAN, C_PLAN, DIS_T, 2D_DIS_T, DIS_TR or 2D_DIS_TR)')
            return
        end if
        n_fit = 0
        do i = 1, size(cells)
            c = cells(i)
            kind = element_for(name, mesh%cell_type(c))
            if (kind == ELEM_NONE) then
                if (skip) cycle
                call set_error(st, STATUS_MODEL_ERROR, 'MODELISATION ' // name // &
                    ' has no element on ' // cell_label(mesh, c, group) // ' of type ' // &
                    trim(CELL_TYPE_NAMES(mesh%cell_type(c))) // ' (' // fitting_types(name) &
                    // ')')
                return
            end if
            model%element(c) = kind
            n_fit = n_fit + 1
        end do
        if (n_fit == 0 .and. size(cells) > 0) call set_error(st, STATUS_MODEL_ERROR, &
            'MODELISATION ' // name // ' fits no cell of the mesh (' // fitting_types(name) &
            // ')')
    end subroutine assign_modelisation

    pure function fitting_types(name) result(text)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        integer(i4) :: k, t
        text = ''
        do k = 1, size(CELL_TYPE_ORDER)
            t = CELL_TYPE_ORDER(k)
            if (element_for(name, t) <= ELEM_NONE) cycle
            if (len(text) > 0) text = text // ', '
            text = text // trim(CELL_TYPE_NAMES(t))
        end do
        text = 'it applies to ' // text
    end function fitting_types

    !> Predicates on element kinds.
    elemental logical function is_plate(kind)
        integer(i4), intent(in) :: kind
        is_plate = kind == ELEM_DKQ .or. kind == ELEM_DKT
    end function is_plate

    !> D_PLAN / C_PLAN solids (surface cells).
    elemental logical function is_plane_solid(kind)
        integer(i4), intent(in) :: kind
        is_plane_solid = (any(kind == D_PLAN_KINDS) .or. any(kind == C_PLAN_KINDS)) .and. &
            .not. is_plane_edge(kind) .and. kind /= ELEM_NONE
    end function is_plane_solid

    !> D_PLAN / C_PLAN edges (SEG2, SEG3).
    elemental logical function is_plane_edge(kind)
        integer(i4), intent(in) :: kind
        is_plane_edge = kind == ELEM_D_PLAN_SEG2 .or. kind == ELEM_C_PLAN_SEG2 .or. &
            kind == ELEM_D_PLAN_SEG3 .or. kind == ELEM_C_PLAN_SEG3
    end function is_plane_edge

    !> DKT edges (SEG2 of a DKT model, MEBODKT).
    elemental logical function is_plate_edge(kind)
        integer(i4), intent(in) :: kind
        is_plate_edge = kind == ELEM_DKT_SEG2
    end function is_plate_edge

    !> Edges that carry loads only (no stiffness): plane edges and plate edges.
    elemental logical function is_load_edge(kind)
        integer(i4), intent(in) :: kind
        is_load_edge = is_plane_edge(kind) .or. is_plate_edge(kind)
    end function is_load_edge

    !> D_PLAN kinds (plane strain), solids and edges.
    elemental logical function is_plane_strain(kind)
        integer(i4), intent(in) :: kind
        is_plane_strain = any(kind == D_PLAN_KINDS) .and. kind /= ELEM_NONE
    end function is_plane_strain

    !> Any discrete (DIS_T, 2D_DIS_T, DIS_TR, 2D_DIS_TR).
    elemental logical function is_discrete(kind)
        integer(i4), intent(in) :: kind
        is_discrete = kind == ELEM_DIS_T_SEG2 .or. kind == ELEM_DIS_T_POI1 .or. &
            kind == ELEM_2D_DIS_T_SEG2 .or. kind == ELEM_2D_DIS_T_POI1 .or. &
            is_discrete_rotational(kind)
    end function is_discrete

    elemental logical function is_discrete_2d(kind)
        integer(i4), intent(in) :: kind
        is_discrete_2d = kind == ELEM_2D_DIS_T_SEG2 .or. kind == ELEM_2D_DIS_T_POI1 .or. &
            kind == ELEM_2D_DIS_TR_SEG2 .or. kind == ELEM_2D_DIS_TR_POI1
    end function is_discrete_2d

    !> DIS_TR and 2D_DIS_TR (rotations too).
    elemental logical function is_discrete_rotational(kind)
        integer(i4), intent(in) :: kind
        is_discrete_rotational = kind == ELEM_DIS_TR_SEG2 .or. kind == ELEM_DIS_TR_POI1 .or. &
            kind == ELEM_2D_DIS_TR_SEG2 .or. kind == ELEM_2D_DIS_TR_POI1
    end function is_discrete_rotational

    !> Number of cells that carry an element.
    integer(i4) function n_modelled_cells(model)
        type(model_t), intent(in) :: model
        n_modelled_cells = count(model%element /= ELEM_NONE, kind=i4)
    end function n_modelled_cells

end module model_types
