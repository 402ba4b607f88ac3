!> The result of an analysis (concepts `evol_elas` of MECA_STATIQUE and `evol_noli` of
!> STAT_NON_LINE): the analysis's raw state per stored instant, the structure it was computed
!> on, and (inherited from result_fields_t) the fields stored per instant by later commands
!> (CALC_CHAMP, ...). doc/architecture.md, "Fields and results".
!>
!> Storage follows Code_Aster: NUME_ORDRE 0 is the initial state (INST_INIT), then one
!> stored instant per converged step. The raw state is kept as equation vectors of the DOF
!> numbering (before renumbering), so a node has exactly the components its elements use:
!>   depl      displacements (imposed values included);
!>   forc_noda nodal internal forces f_int(u);
!>   reac_noda reactions f_int(u) - f_ext on the imposed equations, 0 elsewhere.
!> Spring (discrete) results, for DIS_CHOC: per spring cell, the contact status and the
!> normal force (negative in compression) per stored instant, and Code_Aster's element
!> fields (element_spring_fields):
!>   SIEF_ELGA discrete forces in the element frame, N VY VZ (N VY in 2D), POINT 1 and 2;
!>   VARI_ELGA the DIS_CHOC internal variables V1 .. V10 (V4: 0 in contact, 2 open).
!> Both points of a spring hold the same values (as Code_Aster's DIS_CHOC), stored once.
!> The fields DEPL, FORC_NODA, REAC_NODA, SIEF_ELGA and VARI_ELGA are made from this state
!> by the post layer when a command asks for them (result_access); fields computed later
!> are stored in the inherited field store.
!>
!> The structure (model, materials, element characteristics, the behaviour of each cell) is
!> a copy, kept so that CALC_CHAMP computes on what the analysis used.
module analysis_result
    use kinds, only: dp, i4
    use status, only: status_t, set_error, clear_status, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use mesh_types, only: mesh_t, mesh_release
    use model_dof_numbering, only: dof_numbering_t, component_index
    use mesh_types, only: cell_name
    use model_types, only: model_t
    use model_material, only: material_field_t
    use model_cara_elem, only: cara_elem_t
    use element_spring_fields, only: SPRING_POINTS, DIS_CHOC_N_VARI, sief_component_index, &
        vari_component_index
    use result_fields, only: result_fields_t, result_fields_init, result_add_instant, &
        result_find, RESULT_INST_PRECISION
    implicit none
    private

    public :: RESULT_INST_PRECISION, result_find

    type, extends(result_fields_t), public :: result_concept_t
        type(mesh_t) :: mesh                           !< the mesh the fields live on
        type(dof_numbering_t) :: dofs                  !< equation of (component, node)
        !> The structure of the analysis (copies): CALC_CHAMP computes on it.
        logical :: has_structure = .false.
        type(model_t) :: model
        type(material_field_t) :: materials
        type(cara_elem_t) :: cara
        logical, allocatable :: choc(:)                !< (n_cells) a contact law
        character(len=:), allocatable :: model_name    !< the MODELE concept, for messages
        !> The raw state (see the module header); allocated by result_init only.
        logical :: has_state = .false.
        real(dp), allocatable :: depl(:, :)            !< (n_equations, capacity)
        real(dp), allocatable :: forc_noda(:, :)       !< (n_equations, capacity)
        real(dp), allocatable :: reac_noda(:, :)       !< (n_equations, capacity)
        integer(i4), allocatable :: spring_cell(:)     !< (n_springs) DIS_CHOC cells
        logical, allocatable :: spring_closed(:, :)    !< (n_springs, capacity)
        real(dp), allocatable :: spring_force(:, :)    !< (n_springs, capacity) normal force
        integer(i4) :: spring_dim = 3                  !< 3 (DIS_T) or 2 (2D_DIS_T)
        real(dp), allocatable :: spring_sief(:, :, :)  !< (3, n_springs, capacity) N VY VZ
        real(dp), allocatable :: spring_vari(:, :, :)  !< (DIS_CHOC_N_VARI, n_springs, capacity)
    contains
        procedure :: summary => result_summary
        final :: result_concept_final
    end type result_concept_t

    public :: result_init, result_reserve, result_store, result_node_value, &
        result_store_spring_fields, result_cell_value, is_cell_field, result_set_structure, &
        result_continue

contains

    !> Frees the mesh explicitly: the finalization gfortran 12 generates for this type
    !> leaves part of mesh_t (its name indexes) allocated, as for mesh_concept_t (see there);
    !> found by valgrind (CTest valgrind.*).
    subroutine result_concept_final(self)
        type(result_concept_t), intent(inout) :: self
        call mesh_release(self%mesh)
    end subroutine result_concept_final

    !> One line for the .mess: kind, instants stored, equations.
    function result_summary(self) result(text)
        class(result_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = self%type_name() // ' with ' // to_text(self%n_stored) // &
            ' stored instants, ' // to_text(self%dofs%n_equations) // ' equations'
        if (self%n_stored > 0) text = text // ', INST ' // real_e13(self%inst(1)) // &
            ' to ' // real_e13(self%inst(self%n_stored))
    end function result_summary

    !> Records the structure an analysis ran on (copies of the model, materials, element
    !> characteristics and contact-law cells): CALC_CHAMP computes on it.
    !>  choc       : in, (n_cells) cells with a contact law (DIS_CHOC, DIS_CONTACT)
    !>  model_name : in, the MODELE concept's name, for messages
    subroutine result_set_structure(res, model, materials, cara, choc, model_name)
        type(result_concept_t), intent(inout) :: res
        type(model_t), intent(in) :: model
        type(material_field_t), intent(in) :: materials
        type(cara_elem_t), intent(in) :: cara
        logical, intent(in) :: choc(:)
        character(len=*), intent(in) :: model_name
        res%has_structure = .true.
        res%model = model
        res%materials = materials
        res%cara = cara
        res%choc = choc
        res%model_name = model_name
    end subroutine result_set_structure

    !> STAT_NON_LINE(reuse=R, ETAT_INIT=_F(EVOL_NOLI=R)) changes R in place: the new run
    !> `later`, whose first instant is the state of R's stored instant k, continues R
    !> (Code_Aster keeps the instants before the initial state and numbers the new ones
    !> after it: later's NUME_ORDRE i becomes R's NUME_ORDRE of k plus i; R's instants after
    !> k are dropped). The raw state and the stored fields of both are kept.
    !>  st : STATUS_MODEL_ERROR when the two are not on the same equations and springs
    subroutine result_continue(res, k, later, st)
        type(result_concept_t), intent(inout) :: res
        integer(i4), intent(in) :: k
        type(result_concept_t), intent(in) :: later
        type(status_t), intent(out) :: st
        integer(i4) :: n, m, shift
        call clear_status(st)
        if (.not. res%has_state .or. later%dofs%n_equations /= res%dofs%n_equations &
            .or. size(later%spring_cell) /= size(res%spring_cell)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the result of ETAT_INIT is not on the ' // &
                'equations and springs of this analysis (' // &
                to_text(res%dofs%n_equations) // ' equations, ' // &
                to_text(size(res%spring_cell)) // ' springs; here ' // &
                to_text(later%dofs%n_equations) // ', ' // to_text(size(later%spring_cell)) &
                // ')')
            return
        end if
        if (any(later%spring_cell /= res%spring_cell)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the result of ETAT_INIT has other ' // &
                'contact springs than this analysis')
            return
        end if
        m = k - 1
        n = later%n_stored
        shift = res%nume_ordre(k)
        res%nume_ordre = [res%nume_ordre(1:m), later%nume_ordre(1:n) + shift]
        res%inst = [res%inst(1:m), later%inst(1:n)]
        res%stored = [res%stored(1:m), later%stored(1:n)]
        res%n_stored = m + n
        res%depl = reshape([res%depl(:, 1:m), later%depl(:, 1:n)], [size(res%depl, 1), m + n])
        res%forc_noda = reshape([res%forc_noda(:, 1:m), later%forc_noda(:, 1:n)], &
            [size(res%forc_noda, 1), m + n])
        res%reac_noda = reshape([res%reac_noda(:, 1:m), later%reac_noda(:, 1:n)], &
            [size(res%reac_noda, 1), m + n])
        res%spring_closed = reshape([res%spring_closed(:, 1:m), &
            later%spring_closed(:, 1:n)], [size(res%spring_closed, 1), m + n])
        res%spring_force = reshape([res%spring_force(:, 1:m), later%spring_force(:, 1:n)], &
            [size(res%spring_force, 1), m + n])
        res%spring_sief = reshape([res%spring_sief(:, :, 1:m), later%spring_sief(:, :, 1:n)], &
            [size(res%spring_sief, 1), size(res%spring_sief, 2), m + n])
        res%spring_vari = reshape([res%spring_vari(:, :, 1:m), later%spring_vari(:, :, 1:n)], &
            [size(res%spring_vari, 1), size(res%spring_vari, 2), m + n])
    end subroutine result_continue

    !> Prepares an empty result for `capacity` instants.
    !>  res      : out, the result
    !>  kind     : in, 'evol_elas' or 'evol_noli'
    !>  mesh     : in, copied (IMPR_RESU writes the mesh with the fields)
    !>  dofs     : in, copied
    !>  capacity : in, number of instants that will be stored (NUME_ORDRE 0 included)
    !>  spring_cell : in, optional, the DIS_CHOC cells whose status/force are stored
    subroutine result_init(res, kind, mesh, dofs, capacity, spring_cell)
        type(result_concept_t), intent(out) :: res
        character(len=*), intent(in) :: kind
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        integer(i4), intent(in) :: capacity
        integer(i4), intent(in), optional :: spring_cell(:)
        integer(i4) :: n_springs
        call result_fields_init(res, kind, capacity)
        res%mesh = mesh
        res%dofs = dofs
        res%has_state = .true.
        allocate (res%depl(dofs%n_equations, capacity), res%forc_noda(dofs%n_equations, &
            capacity), res%reac_noda(dofs%n_equations, capacity))
        n_springs = 0
        if (present(spring_cell)) n_springs = size(spring_cell)
        allocate (res%spring_cell(n_springs), res%spring_closed(n_springs, capacity), &
            res%spring_force(n_springs, capacity))
        allocate (res%spring_sief(3, n_springs, capacity), &
            res%spring_vari(DIS_CHOC_N_VARI, n_springs, capacity), source=0.0_dp)
        if (present(spring_cell)) res%spring_cell = spring_cell
    end subroutine result_init

    !> Makes room for `capacity` instants in the raw state (the instants a STAT_NON_LINE step
    !> cut by DEFI_LIST_INST/ECHEC adds; the stored instants grow by themselves,
    !> result_add_instant); what is stored is kept.
    subroutine result_reserve(res, capacity)
        type(result_concept_t), intent(inout) :: res
        integer(i4), intent(in) :: capacity
        integer(i4) :: n
        if (capacity <= size(res%depl, 2)) return
        n = res%n_stored
        call grow_r2(res%depl)
        call grow_r2(res%forc_noda)
        call grow_r2(res%reac_noda)
        call grow_l2(res%spring_closed)
        call grow_r2(res%spring_force)
        call grow_r3(res%spring_sief)
        call grow_r3(res%spring_vari)
    contains
        subroutine grow_r2(a)
            real(dp), allocatable, intent(inout) :: a(:, :)
            real(dp), allocatable :: b(:, :)
            allocate (b(size(a, 1), capacity))
            b(:, 1:n) = a(:, 1:n)
            call move_alloc(b, a)
        end subroutine grow_r2
        subroutine grow_l2(a)
            logical, allocatable, intent(inout) :: a(:, :)
            logical, allocatable :: b(:, :)
            allocate (b(size(a, 1), capacity))
            b(:, 1:n) = a(:, 1:n)
            call move_alloc(b, a)
        end subroutine grow_l2
        subroutine grow_r3(a)
            real(dp), allocatable, intent(inout) :: a(:, :, :)
            real(dp), allocatable :: b(:, :, :)
            allocate (b(size(a, 1), size(a, 2), capacity), source=0.0_dp)
            b(:, :, 1:n) = a(:, :, 1:n)
            call move_alloc(b, a)
        end subroutine grow_r3
    end subroutine result_reserve

    !> Stores one instant (the next NUME_ORDRE).
    !>  depl, forc_noda, reac_noda : in, (n_equations) fields at this instant
    !>  spring_closed, spring_force : in, optional, (n_springs) spring state
    subroutine result_store(res, nume_ordre, inst, depl, forc_noda, reac_noda, &
                            spring_closed, spring_force)
        type(result_concept_t), intent(inout) :: res
        integer(i4), intent(in) :: nume_ordre
        real(dp), intent(in) :: inst
        real(dp), intent(in) :: depl(:), forc_noda(:), reac_noda(:)
        logical, intent(in), optional :: spring_closed(:)
        real(dp), intent(in), optional :: spring_force(:)
        integer(i4) :: k
        call result_add_instant(res, nume_ordre, inst, k)
        res%depl(:, k) = depl
        res%forc_noda(:, k) = forc_noda
        res%reac_noda(:, k) = reac_noda
        if (present(spring_closed)) res%spring_closed(:, k) = spring_closed
        if (present(spring_force)) res%spring_force(:, k) = spring_force
    end subroutine result_store

    !> Value of component `component` (e.g. 'DZ') of field `field` ('DEPL', 'FORC_NODA',
    !> 'REAC_NODA') at node `node` for stored instant `index`.
    !>  st : STATUS_MODEL_ERROR when the node has no such component or the field is unknown
    subroutine result_node_value(res, field, index, node, component, value, st)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field, component
        integer(i4), intent(in) :: index, node
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        integer(i4) :: comp, eq
        value = 0.0_dp
        comp = component_index(component)
        eq = 0
        if (comp > 0) eq = res%dofs%equation(comp, node)
        if (eq == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the node has no component ' // &
                component // ' (its elements do not use it)')
            return
        end if
        select case (field)
        case ('DEPL')
            value = res%depl(eq, index)
        case ('FORC_NODA')
            value = res%forc_noda(eq, index)
        case ('REAC_NODA')
            value = res%reac_noda(eq, index)
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'field ' // field // &
                ' is not stored (DEPL, FORC_NODA, REAC_NODA)')
        end select
    end subroutine result_node_value

    !> Stores the spring fields of the last stored instant (spring_results).
    !>  ndim : in, 3 (DIS_T) or 2 (2D_DIS_T)
    !>  sief : in, (3, n_springs) N VY VZ;  vari : in, (DIS_CHOC_N_VARI, n_springs)
    subroutine result_store_spring_fields(res, ndim, sief, vari)
        type(result_concept_t), intent(inout) :: res
        integer(i4), intent(in) :: ndim
        real(dp), intent(in) :: sief(:, :), vari(:, :)
        if (res%n_stored < 1) return
        res%spring_dim = ndim
        res%spring_sief(:, :, res%n_stored) = sief
        res%spring_vari(:, :, res%n_stored) = vari
    end subroutine result_store_spring_fields

    !> True for the element fields (SIEF_ELGA, VARI_ELGA), read at a cell and a point.
    pure logical function is_cell_field(field)
        character(len=*), intent(in) :: field
        is_cell_field = field == 'SIEF_ELGA' .or. field == 'VARI_ELGA'
    end function is_cell_field

    !> Value of component `component` of element field `field` (SIEF_ELGA: N VY VZ;
    !> VARI_ELGA: V1 .. V10) at point `point` of cell `cell` for stored instant `index`.
    !>  st : STATUS_MODEL_ERROR naming the cell when it holds no such field (the fields are
    !>       stored for DIS_CHOC springs only), the point or the component when they do not
    !>       exist there
    subroutine result_cell_value(res, field, index, cell, point, component, value, st)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field, component
        integer(i4), intent(in) :: index, cell, point
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        integer(i4) :: k, c
        value = 0.0_dp
        k = findloc(res%spring_cell, cell, dim=1)
        if (k == 0) then
            call set_error(st, STATUS_MODEL_ERROR, field // ' is not stored at cell ' // &
                cell_name(res%mesh, cell) // ': parasol stores it for the DIS_CHOC ' // &
                'springs of STAT_NON_LINE only (' // to_text(size(res%spring_cell, kind=i4)) &
                // ' in this result)')
            return
        end if
        if (point < 1 .or. point > SPRING_POINTS) then
            call set_error(st, STATUS_MODEL_ERROR, 'cell ' // cell_name(res%mesh, cell) // &
                ' has points 1 and 2 (the Gauss points of a SEG2 discrete sit at its ' // &
                'nodes), not ' // to_text(point))
            return
        end if
        select case (field)
        case ('SIEF_ELGA')
            c = sief_component_index(component, res%spring_dim)
            if (c > 0) value = res%spring_sief(c, k, index)
            if (c == 0) call set_error(st, STATUS_MODEL_ERROR, 'SIEF_ELGA of a ' // &
                trim(merge('DIS_T   ', '2D_DIS_T', res%spring_dim == 3)) // &
                ' spring has components ' // trim(merge('N VY VZ', 'N VY   ', &
                res%spring_dim == 3)) // ', not ' // component)
        case ('VARI_ELGA')
            c = vari_component_index(component, DIS_CHOC_N_VARI)
            if (c > 0) value = res%spring_vari(c, k, index)
            if (c == 0) call set_error(st, STATUS_MODEL_ERROR, 'VARI_ELGA of DIS_CHOC ' // &
                'has components V1 to V' // to_text(DIS_CHOC_N_VARI) // ', not ' // component)
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'field ' // field // &
                ' is not an element field (SIEF_ELGA, VARI_ELGA)')
        end select
    end subroutine result_cell_value

end module analysis_result
