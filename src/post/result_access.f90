!> The fields of a result as commands read them (TEST_RESU, IMPR_RESU, CREA_CHAMP EXTR,
!> CALC_CHAMP): a field stored in the result, or one made from the analysis's raw state the
!> first time a command asks for it, then stored (doc/architecture.md, "Fields and
!> results"). The fields an analysis provides this way are those Code_Aster's MECA_STATIQUE
!> and STAT_NON_LINE store:
!>   DEPL       NOEU_DEPL_R, the components each node's elements use;
!>   SIEF_ELGA  ELGA_SIEF_R, the state of stress (element_fields): plates' stresses at
!>              their layer sub-points, the discrete springs' forces N VY VZ;
!>   VARI_ELGA  ELGA_VARI_R, the DIS_CHOC internal variables V1 .. V10;
!> and the nodal forces parasol's analyses compute anyway (Code_Aster's CALC_CHAMP FORCE
!> options give the same fields): FORC_NODA and REAC_NODA, NOEU_DEPL_R.
!> Any other field must have been computed (CALC_CHAMP, POST_CHAMP, CREA_RESU): asking for
!> it is an error naming what is stored and the command that computes it.
module result_access
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper
    use mesh_types, only: mesh_t
    use model_dof_numbering, only: N_COMPONENTS, COMPONENT_NAMES
    use element_spring_fields, only: SPRING_POINTS, DIS_CHOC_N_VARI, SIEF_COMPONENTS
    use field_types, only: field_t, component_set_t, field_init_nodes, field_init_cells, &
        field_define_cells, FIELD_ELGA
    use field_quantities, only: quantity_components
    use result_fields, only: result_fields_t, result_field_index, result_put_field, &
        result_stored_names
    use analysis_result, only: result_concept_t
    use element_fields, only: state_sief_elga
    implicit none
    private

    !> Fields an analysis result can give without CALC_CHAMP (module header).
    character(len=*), parameter, public :: STATE_FIELDS = 'DEPL FORC_NODA REAC_NODA ' // &
        'SIEF_ELGA VARI_ELGA'

    public :: result_field_at, result_nodal_from_state, result_mesh, option_family, &
        result_field_names

contains

    !> Every field a result has at stored instant `at`: for an analysis, DEPL, the nodal
    !> forces FORC_NODA and REAC_NODA (Code_Aster's need CALC_CHAMP FORCE; parasol's
    !> analyses have them anyway) and SIEF_ELGA (STAT_NON_LINE with DIS_CHOC springs also
    !> VARI_ELGA), then the fields stored there (CALC_CHAMP, POST_CHAMP, CREA_RESU), each
    !> once.
    function result_field_names(res, at) result(names)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: at
        type(string_t), allocatable :: names(:)
        type(string_t), allocatable :: stored(:)
        character(len=:), allocatable :: listed
        integer :: k
        allocate (names(0))
        listed = ' '
        select type (res)
        type is (result_concept_t)
            if (res%has_state) then
                call add('DEPL')
                call add('FORC_NODA')
                call add('REAC_NODA')
                if (res%has_structure) call add('SIEF_ELGA')
                if (res%type_name() == 'evol_noli' .and. allocated(res%spring_cell)) then
                    if (size(res%spring_cell) > 0) call add('VARI_ELGA')
                end if
            end if
        end select
        if (at < 1 .or. at > res%n_stored) return
        stored = result_stored_names(res, at)
        do k = 1, size(stored)
            call add(stored(k)%s)
        end do
    contains
        subroutine add(name)
            character(len=*), intent(in) :: name
            type(string_t), allocatable :: bigger(:)
            integer :: n
            if (index(listed, ' ' // name // ' ') > 0) return
            listed = listed // name // ' '
            n = size(names)
            allocate (bigger(n + 1))
            bigger(1:n) = names
            bigger(n + 1)%s = name
            call move_alloc(bigger, names)
        end subroutine add
    end function result_field_names

    !> Field `name` of `res` at stored instant `at` (1..n_stored): the stored one, else
    !> one made from the analysis's state (STATE_FIELDS) and stored.
    !>  f  : out, points into res
    !>  st : STATUS_MODEL_ERROR when the field is neither stored nor made from the state
    !>       (naming what is stored and the command that computes it)
    subroutine result_field_at(res, at, name, f, st)
        class(result_fields_t), target, intent(inout) :: res
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        type(field_t), pointer, intent(out) :: f
        type(status_t), intent(out) :: st
        type(field_t) :: made
        integer(i4) :: k
        character(len=:), allocatable :: field_name
        f => null()
        field_name = to_upper(trim(name))
        if (at < 1 .or. at > res%n_stored) then
            call set_error(st, STATUS_MODEL_ERROR, 'instant ' // to_text(at) // &
                ' is not stored (the result holds ' // to_text(res%n_stored) // ')')
            return
        end if
        k = result_field_index(res, at, field_name)
        if (k == 0) then
            select type (res)
            type is (result_concept_t)
                if (res%has_state .and. index(' ' // state_fields_of(res) // ' ', ' ' // &
                    field_name // ' ') > 0) then
                    call field_from_state(res, at, field_name, made, st)
                    if (st%failed()) return
                    call result_put_field(res, at, field_name, made)
                    k = result_field_index(res, at, field_name)
                end if
            end select
        end if
        if (k == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'field ' // field_name // &
                ' is not computed in the result at NUME_ORDRE ' // &
                to_text(res%nume_ordre(at)) // ' (' // available_text(res, at) // &
                ')' // how_to_compute(field_name))
            return
        end if
        f => res%stored(at)%items(k)%field
    end subroutine result_field_at

    !> The STATE_FIELDS a result can make: VARI_ELGA only for STAT_NON_LINE (evol_noli),
    !> whose behaviours have internal variables.
    function state_fields_of(res) result(names)
        type(result_concept_t), intent(in) :: res
        character(len=:), allocatable :: names
        names = 'DEPL FORC_NODA REAC_NODA SIEF_ELGA'
        if (res%type_name() == 'evol_noli') names = names // ' VARI_ELGA'
    end function state_fields_of

    !> What a result holds at an instant, for messages.
    function available_text(res, at) result(text)
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: at
        character(len=:), allocatable :: text
        type(string_t), allocatable :: names(:)
        integer :: k
        character(len=:), allocatable :: all
        names = result_stored_names(res, at)
        all = ''
        select type (res)
        type is (result_concept_t)
            if (res%has_state) all = state_fields_of(res)
        end select
        do k = 1, size(names)
            if (index(' ' // all // ' ', ' ' // names(k)%s // ' ') > 0) cycle
            if (len(all) > 0) all = all // ' '
            all = all // names(k)%s
        end do
        if (len(all) == 0) then
            text = 'it holds no field there'
        else
            text = 'it has ' // all
        end if
    end function available_text

    !> The command that computes a field, as a sentence to append to a message.
    pure function how_to_compute(name) result(text)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        text = ''
        select case (name)
        case ('SIGM_ELNO', 'SIGM_ELGA', 'SIGM_NOEU', 'EFGE_ELNO', 'EFGE_ELGA', 'EFGE_NOEU', &
              'SIEF_ELNO', 'SIEF_NOEU', 'SIPO_ELNO', 'SIPM_ELNO')
            text = ': compute it with CALC_CHAMP(CONTRAINTE=''' // name // ''')'
        case ('EPSI_ELNO', 'EPSI_ELGA', 'EPSI_NOEU', 'DEGE_ELNO', 'DEGE_ELGA', 'DEGE_NOEU', &
              'EPME_ELNO', 'EPME_ELGA', 'EPSG_ELGA', 'EPSG_ELNO')
            text = ': compute it with CALC_CHAMP(DEFORMATION=''' // name // ''')'
        case ('SIEQ_ELNO', 'SIEQ_ELGA', 'SIEQ_NOEU', 'EPEQ_ELNO', 'EPEQ_ELGA', 'EPEQ_NOEU')
            text = ': compute it with CALC_CHAMP(CRITERES=''' // name // ''')'
        case ('ENEL_ELEM', 'ENEL_ELGA', 'ENEL_ELNO', 'ENEL_NOEU', 'EPOT_ELEM', 'ETOT_ELEM', &
              'ETOT_ELGA', 'ETOT_ELNO')
            text = ': compute it with CALC_CHAMP(ENERGIE=''' // name // ''')'
        end select
    end function how_to_compute

    !> Makes one of STATE_FIELDS from the raw state.
    subroutine field_from_state(res, at, name, f, st)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        select case (name)
        case ('DEPL')
            call result_nodal_from_state(res, res%depl(:, at), f, st)
        case ('FORC_NODA')
            call result_nodal_from_state(res, res%forc_noda(:, at), f, st)
        case ('REAC_NODA')
            call result_nodal_from_state(res, res%reac_noda(:, at), f, st)
        case ('SIEF_ELGA')
            call state_sief_elga(res, at, f, st)
        case ('VARI_ELGA')
            call spring_field(res, at, name, f, st)
        end select
    end subroutine field_from_state

    !> A NOEU_DEPL_R field from an equation vector of the result's DOF numbering: every
    !> component some node has, each node with exactly its own.
    !>  values : in, (n_equations)
    subroutine result_nodal_from_state(res, values, f, st)
        type(result_concept_t), intent(in) :: res
        real(dp), intent(in) :: values(:)
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: cmps(:)
        logical :: used(N_COMPONENTS)
        integer(i4) :: c, n, k, eq
        used = any(res%dofs%equation > 0, dim=2)
        allocate (cmps(count(used)))
        k = 0
        do c = 1, N_COMPONENTS
            if (.not. used(c)) cycle
            k = k + 1
            cmps(k)%s = trim(COMPONENT_NAMES(c))
        end do
        call field_init_nodes(f, 'DEPL_R', cmps, res%dofs%n_nodes, st)
        if (st%failed()) return
        k = 0
        do c = 1, N_COMPONENTS
            if (.not. used(c)) cycle
            k = k + 1
            do n = 1, res%dofs%n_nodes
                eq = res%dofs%equation(c, n)
                if (eq == 0) cycle
                f%node_has(k, n) = .true.
                f%node_values(k, n) = values(eq)
            end do
        end do
    end subroutine result_nodal_from_state

    !> SIEF_ELGA or VARI_ELGA of the DIS_CHOC springs (2 points, the same values).
    subroutine spring_field(res, at, name, f, st)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: cmps(:)
        type(component_set_t) :: sets(1)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        integer(i4) :: k, c, p, n_cmp
        integer(i4) :: j
        if (name == 'SIEF_ELGA') then
            n_cmp = res%spring_dim
            allocate (cmps(n_cmp))
            do j = 1, n_cmp
                cmps(j)%s = trim(SIEF_COMPONENTS(j))
            end do
            call field_init_cells(f, FIELD_ELGA, 'SIEF_R', cmps, res%mesh%n_cells, st)
        else
            n_cmp = DIS_CHOC_N_VARI
            cmps = quantity_components('VARI_R', DIS_CHOC_N_VARI)
            call field_init_cells(f, FIELD_ELGA, 'VARI_R', cmps, res%mesh%n_cells, st)
        end if
        if (st%failed()) return
        allocate (n_points(res%mesh%n_cells), n_sub(res%mesh%n_cells), &
            cell_set(res%mesh%n_cells), source=0_i4)
        n_points(res%spring_cell) = SPRING_POINTS
        n_sub(res%spring_cell) = 1
        cell_set(res%spring_cell) = 1
        sets(1)%cmp = [(j, j = 1, n_cmp)]
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do k = 1, size(res%spring_cell)
            c = res%spring_cell(k)
            do p = 1, SPRING_POINTS
                if (name == 'SIEF_ELGA') then
                    f%values(f%offset(c) + (p - 1) * n_cmp + 1:f%offset(c) + p * n_cmp) = &
                        res%spring_sief(1:n_cmp, k, at)
                else
                    f%values(f%offset(c) + (p - 1) * n_cmp + 1:f%offset(c) + p * n_cmp) = &
                        res%spring_vari(1:n_cmp, k, at)
                end if
            end do
        end do
    end subroutine spring_field

    !> The mesh of a result (its nodes and cells are the fields' numbering).
    !>  st : STATUS_MODEL_ERROR for a result that knows no mesh
    subroutine result_mesh(res, mesh, st)
        class(result_fields_t), target, intent(in) :: res
        type(mesh_t), pointer, intent(out) :: mesh
        type(status_t), intent(out) :: st
        mesh => null()
        select type (res)
        type is (result_concept_t)
            mesh => res%mesh
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'the result knows no mesh')
        end select
    end subroutine result_mesh

    !> The option family of a field name (CONTRAINTE, DEFORMATION, ...), '' if none: for
    !> messages that say which CALC_CHAMP keyword computes it.
    pure function option_family(name) result(family)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: family
        character(len=:), allocatable :: text
        text = how_to_compute(name)
        family = ''
        if (index(text, 'CONTRAINTE') > 0) family = 'CONTRAINTE'
        if (index(text, 'DEFORMATION') > 0) family = 'DEFORMATION'
        if (index(text, 'CRITERES') > 0) family = 'CRITERES'
        if (index(text, 'ENERGIE') > 0) family = 'ENERGIE'
    end function option_family

end module result_access
