!> The result of an analysis (concepts `evol_elas` of MECA_STATIQUE and `evol_noli` of
!> STAT_NON_LINE): the fields stored per instant, read by TEST_RESU and IMPR_RESU.
!>
!> Storage follows Code_Aster: NUME_ORDRE 0 is the initial state (INST_INIT), then one
!> stored instant per converged step. Nodal fields are kept as equation vectors of the DOF
!> numbering (before renumbering), so a node has exactly the components its elements use.
!>   DEPL      displacements (imposed values included);
!>   FORC_NODA nodal internal forces f_int(u);
!>   REAC_NODA reactions f_int(u) - f_ext on the imposed equations, 0 elsewhere.
!> Spring (discrete) results, for DIS_CHOC: per spring cell, the contact status and the
!> normal force (negative in compression) per stored instant.
module analysis_result
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use deck_concept, only: concept_t
    use mesh_types, only: mesh_t
    use model_dof_numbering, only: dof_numbering_t, component_index
    implicit none
    private

    !> Relative tolerance for matching a requested INST to a stored one (Code_Aster's
    !> TEST_RESU/IMPR_RESU default PRECISION for instants, CRITERE='RELATIF': 1e-6).
    real(dp), parameter, public :: RESULT_INST_PRECISION = 1.0e-6_dp

    type, extends(concept_t), public :: result_concept_t
        character(len=:), allocatable :: kind          !< 'evol_elas' or 'evol_noli'
        type(mesh_t) :: mesh                           !< the mesh the fields live on
        type(dof_numbering_t) :: dofs                  !< equation of (component, node)
        integer(i4) :: n_stored = 0                    !< instants stored so far
        integer(i4), allocatable :: nume_ordre(:)      !< (capacity) NUME_ORDRE of each
        real(dp), allocatable :: inst(:)               !< (capacity) INST of each
        real(dp), allocatable :: depl(:, :)            !< (n_equations, capacity)
        real(dp), allocatable :: forc_noda(:, :)       !< (n_equations, capacity)
        real(dp), allocatable :: reac_noda(:, :)       !< (n_equations, capacity)
        integer(i4), allocatable :: spring_cell(:)     !< (n_springs) DIS_CHOC cells
        logical, allocatable :: spring_closed(:, :)    !< (n_springs, capacity)
        real(dp), allocatable :: spring_force(:, :)    !< (n_springs, capacity) normal force
    contains
        procedure :: type_name => result_type_name
        procedure :: summary => result_summary
    end type result_concept_t

    public :: result_init, result_store, result_find, result_node_value

contains

    function result_type_name(self) result(name)
        class(result_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'evol_noli'
        if (allocated(self%kind)) name = self%kind
    end function result_type_name

    !> One line for the .mess: kind, instants stored, equations.
    function result_summary(self) result(text)
        class(result_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = self%type_name() // ' with ' // to_text(self%n_stored) // &
            ' stored instants, ' // to_text(self%dofs%n_equations) // ' equations'
        if (self%n_stored > 0) text = text // ', INST ' // real_e13(self%inst(1)) // &
            ' to ' // real_e13(self%inst(self%n_stored))
    end function result_summary

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
        res%kind = kind
        res%mesh = mesh
        res%dofs = dofs
        allocate (res%nume_ordre(capacity), res%inst(capacity))
        allocate (res%depl(dofs%n_equations, capacity), res%forc_noda(dofs%n_equations, &
            capacity), res%reac_noda(dofs%n_equations, capacity))
        n_springs = 0
        if (present(spring_cell)) n_springs = size(spring_cell)
        allocate (res%spring_cell(n_springs), res%spring_closed(n_springs, capacity), &
            res%spring_force(n_springs, capacity))
        if (present(spring_cell)) res%spring_cell = spring_cell
    end subroutine result_init

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
        res%n_stored = res%n_stored + 1
        k = res%n_stored
        res%nume_ordre(k) = nume_ordre
        res%inst(k) = inst
        res%depl(:, k) = depl
        res%forc_noda(:, k) = forc_noda
        res%reac_noda(:, k) = reac_noda
        if (present(spring_closed)) res%spring_closed(:, k) = spring_closed
        if (present(spring_force)) res%spring_force(:, k) = spring_force
    end subroutine result_store

    !> Index (1..n_stored) of the stored instant asked for by INST (within
    !> RESULT_INST_PRECISION, relative, absolute near 0) or by NUME_ORDRE.
    !>  st : STATUS_MODEL_ERROR naming the instant and listing what is stored
    subroutine result_find(res, index, st, inst, nume_ordre)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(out) :: index
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: inst
        integer(i4), intent(in), optional :: nume_ordre
        integer(i4) :: k
        character(len=:), allocatable :: stored
        index = 0
        do k = 1, res%n_stored
            if (present(inst)) then
                if (abs(res%inst(k) - inst) <= RESULT_INST_PRECISION * max(abs(inst), &
                    1.0_dp)) index = k
            else if (present(nume_ordre)) then
                if (res%nume_ordre(k) == nume_ordre) index = k
            end if
            if (index /= 0) return
        end do
        stored = ''
        do k = 1, res%n_stored
            if (k > 1) stored = stored // ', '
            if (present(inst)) then
                stored = stored // real_e13(res%inst(k))
            else
                stored = stored // to_text(res%nume_ordre(k))
            end if
        end do
        if (present(inst)) then
            call set_error(st, STATUS_MODEL_ERROR, 'INST ' // real_e13(inst) // &
                ' is not stored in the result (stored: ' // stored // ')')
        else if (present(nume_ordre)) then
            call set_error(st, STATUS_MODEL_ERROR, 'NUME_ORDRE ' // to_text(nume_ordre) // &
                ' is not stored in the result (stored: ' // stored // ')')
        else
            call set_error(st, STATUS_MODEL_ERROR, 'give INST or NUME_ORDRE')
        end if
    end subroutine result_find

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

end module analysis_result
