!> DOF numbering from the elements present (design.md, layer 5): a node gets exactly the
!> components its elements use, a node with no element gets none. Equations are numbered
!> node by node, components in the order DX DY DZ DRX DRY DRZ (before any renumbering).
module model_dof_numbering
    use kinds, only: i4
    use mesh_types, only: mesh_t, node_name
    use model_types, only: model_t, ELEM_NONE, ELEM_DKQ, ELEM_DKT, ELEM_DIS_T_SEG2, &
        ELEM_DIS_T_POI1, ELEM_2D_DIS_T_SEG2, ELEM_2D_DIS_T_POI1, ELEM_DIS_TR_SEG2, &
        ELEM_DIS_TR_POI1, ELEM_2D_DIS_TR_SEG2, ELEM_2D_DIS_TR_POI1, is_plane_solid, &
        is_plane_edge, ELEM_DKT_SEG2
    implicit none
    private

    !> Components (Code_Aster names).
    integer(i4), parameter, public :: DOF_DX = 1, DOF_DY = 2, DOF_DZ = 3, DOF_DRX = 4, &
        DOF_DRY = 5, DOF_DRZ = 6, N_COMPONENTS = 6
    character(len=3), parameter, public :: COMPONENT_NAMES(N_COMPONENTS) = ['DX ', 'DY ', &
        'DZ ', 'DRX', 'DRY', 'DRZ']

    !> Equation numbers of every (node, component).
    type, public :: dof_numbering_t
        integer(i4) :: n_nodes = 0
        integer(i4) :: n_equations = 0
        integer(i4), allocatable :: equation(:, :)      !< (N_COMPONENTS, n_nodes), 0 = absent
        integer(i4), allocatable :: equation_node(:)    !< (n_equations) node of an equation
        integer(i4), allocatable :: equation_component(:)  !< (n_equations) DOF_* of it
    end type dof_numbering_t

    public :: number_dofs, element_components, equation_of, describe_equation, &
        component_index

contains

    !> Components used by element kind `kind` (a logical mask over DX..DRZ).
    pure function element_components(kind) result(mask)
        integer(i4), intent(in) :: kind
        logical :: mask(N_COMPONENTS)
        mask = .false.
        if (is_plane_solid(kind) .or. is_plane_edge(kind)) then
            mask(DOF_DX:DOF_DY) = .true.
            return
        end if
        select case (kind)
        case (ELEM_DKQ, ELEM_DKT, ELEM_DKT_SEG2, ELEM_DIS_TR_SEG2, ELEM_DIS_TR_POI1)
            mask = .true.
        case (ELEM_2D_DIS_TR_SEG2, ELEM_2D_DIS_TR_POI1)
            mask([DOF_DX, DOF_DY, DOF_DRZ]) = .true.
        case (ELEM_2D_DIS_T_SEG2, ELEM_2D_DIS_T_POI1)
            mask(DOF_DX:DOF_DY) = .true.
        case (ELEM_DIS_T_SEG2, ELEM_DIS_T_POI1)
            mask(DOF_DX:DOF_DZ) = .true.
        case default
        end select
    end function element_components

    !> Numbers the DOFs of `model` on `mesh` into `dofs`.
    subroutine number_dofs(model, mesh, dofs)
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(out) :: dofs
        logical, allocatable :: used(:, :)
        logical :: mask(N_COMPONENTS)
        integer(i4) :: c, p, n, k
        allocate (used(N_COMPONENTS, mesh%n_nodes), source=.false.)
        do c = 1, mesh%n_cells
            if (model%element(c) == ELEM_NONE) cycle
            mask = element_components(model%element(c))
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                used(:, mesh%cell_nodes(p)) = used(:, mesh%cell_nodes(p)) .or. mask
            end do
        end do
        dofs%n_nodes = mesh%n_nodes
        dofs%n_equations = count(used, kind=i4)
        allocate (dofs%equation(N_COMPONENTS, mesh%n_nodes), source=0_i4)
        allocate (dofs%equation_node(dofs%n_equations), dofs%equation_component(dofs%n_equations))
        k = 0
        do n = 1, mesh%n_nodes
            do p = 1, N_COMPONENTS
                if (.not. used(p, n)) cycle
                k = k + 1
                dofs%equation(p, n) = k
                dofs%equation_node(k) = n
                dofs%equation_component(k) = p
            end do
        end do
    end subroutine number_dofs

    !> Equation of (node, component), 0 if that node has no such DOF.
    pure integer(i4) function equation_of(dofs, node, component)
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: node, component
        equation_of = dofs%equation(component, node)
    end function equation_of

    !> DOF_* index of a component name ('DX'..'DRZ'), 0 if unknown.
    pure integer(i4) function component_index(name)
        character(len=*), intent(in) :: name
        integer(i4) :: k
        component_index = 0
        do k = 1, N_COMPONENTS
            if (trim(name) == trim(COMPONENT_NAMES(k))) component_index = k
        end do
    end function component_index

    !> "node N12 component DZ" for equation `eq` (singular-pivot messages).
    function describe_equation(dofs, mesh, eq) result(text)
        type(dof_numbering_t), intent(in) :: dofs
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: eq
        character(len=:), allocatable :: text
        text = 'node ' // node_name(mesh, dofs%equation_node(eq)) // ' component ' // &
            trim(COMPONENT_NAMES(dofs%equation_component(eq)))
    end function describe_equation

end module model_dof_numbering
