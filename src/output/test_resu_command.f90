!> TEST_RESU: checks values of results, fields and meshes against the deck's
!> non-regression value VALE_CALC and, with REFERENCE, against VALE_REFE (listings.md,
!> "TEST_RESU blocks" and "TEST_RESU semantics"). Occurrences, in the order Code_Aster
!> runs them: CHAM_NO, CARTE, CHAM_ELEM (a field concept of CREA_CHAMP), RESU (a field of a
!> result at an instant, or a parameter of it), MAILLAGE (a count of the mesh). Each writes
!> one block to the `.resu`, echoes each check line to the `.mess` and counts it in the run
!> context (NOOK makes the run exit with status 2).
!>
!> The tested instant of a RESU is found by NUME_ORDRE, or by INST within the second
!> TOLE_MACHINE (default 1e-6) and the second CRITERE (default RELATIF; relative is
!> absolute below |INST| = 1). The value in a field is found by test_resu_checks
!> (test_value_in_field): a node, a cell's point and sub-point, or TYPE_TEST over the field.
!> A result's fields are those stored or made from its analysis's state (result_access).
module test_resu_command
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node_group, find_cell_group, nodes_of_group, &
        cells_of_group, n_node_groups, n_cell_groups
    use field_support, only: mesh_of_support
    use field_types, only: field_t
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t, result_find, RESULT_INST_PRECISION
    use analysis_result, only: result_concept_t, result_node_value
    use result_access, only: result_field_at, result_mesh
    use test_resu_format, only: test_check_t
    use test_resu_checks, only: read_checks, write_test_block, add_column, &
        test_value_in_field, test_columns_t, relocate, single_node, single_cell, &
        listing_safe_text, compact_text
    implicit none
    private

    public :: run_test_resu, test_resu_value, test_resu_single_node, listing_safe_text, &
        compact_text, result_of_keyword, result_index_of, relocate, test_resu_single_cell

contains

    !> Handler of TEST_RESU (doc/architecture.md "Writing a command handler").
    !>  st : located errors at the keyword at fault (a concept of another type, an instant
    !>       not stored, a field not computed, a node, cell, point, sub-point or component
    !>       that does not exist, REFERENCE without VALE_REFE or the reverse)
    subroutine run_test_resu(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer :: k, g
        character(len=9), parameter :: GROUPS(3) = ['CHAM_NO  ', 'CARTE    ', 'CHAM_ELEM']
        if (allocated(result)) deallocate (result)     ! TEST_RESU has no result
        do g = 1, size(GROUPS)
            do k = 1, cmd%count(trim(GROUPS(g)))
                call test_field_occurrence(ctx, cmd%occurrence(trim(GROUPS(g)), k), st)
                if (st%failed()) return
            end do
        end do
        do k = 1, cmd%count('RESU')
            call test_result_occurrence(ctx, cmd%occurrence('RESU', k), st)
            if (st%failed()) return
        end do
        do k = 1, cmd%count('MAILLAGE')
            call test_mesh_occurrence(ctx, cmd%occurrence('MAILLAGE', k), st)
            if (st%failed()) return
        end do
    end subroutine run_test_resu

    !> One RESU occurrence: a field's value at an instant (or a parameter of the instant).
    subroutine test_result_occurrence(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        class(result_fields_t), pointer :: res
        type(field_t), pointer :: f
        type(mesh_t), pointer :: mesh
        type(test_check_t), allocatable :: checks(:)
        type(test_columns_t) :: cols
        integer(i4) :: index
        real(dp) :: computed
        logical :: integers
        character(len=:), allocatable :: field_name, component
        call result_of_keyword(occ, 'RESULTAT', res, st)
        if (st%ok()) call result_index_of(occ, res, index, st)
        if (st%ok()) call read_checks(occ, checks, integers, st)
        if (st%failed()) return
        call add_column(cols, 'RESULTAT', res%name)
        call add_column(cols, 'NUME_ORDRE', to_text(res%nume_ordre(index)))
        if (occ%has('INST')) call add_column(cols, 'INST', real_e13(res%inst(index)))
        if (occ%has('PARA')) then
            call parameter_value(occ, res, index, cols, computed, st)
            if (st%failed()) return
            call write_test_block(ctx, cols, checks, computed)
            return
        end if
        call occ%get_text('NOM_CHAM', field_name, st)
        if (st%failed()) return
        component = ''
        if (occ%has('NOM_CMP')) call occ%get_text('NOM_CMP', component, st)
        if (occ%has('NOM_VARI')) call occ%get_text('NOM_VARI', component, st)
        if (st%failed()) return
        call add_column(cols, 'NOM_CHAM', field_name)
        if (len(component) > 0) call add_column(cols, 'NOM_CMP', component)
        call result_field_at(res, index, field_name, f, st)
        if (st%failed()) then
            call relocate(occ, 'NOM_CHAM', st)
            return
        end if
        call result_mesh(res, mesh, st)
        if (st%failed()) then
            call relocate(occ, 'RESULTAT', st)
            return
        end if
        call test_value_in_field(ctx, occ, f, mesh, field_name, component, cols, computed, st)
        if (st%failed()) return
        if (occ%has('VALE_ABS')) call vale_abs_column(occ, cols)
        call write_test_block(ctx, cols, checks, computed)
    end subroutine test_result_occurrence

    !> PARA: a parameter of the stored instant (INST).
    subroutine parameter_value(occ, res, index, cols, value, st)
        type(keyword_set_t), intent(in) :: occ
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: index
        type(test_columns_t), intent(inout) :: cols
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name
        value = 0.0_dp
        call occ%get_text('PARA', name, st)
        if (st%failed()) return
        call add_column(cols, 'PARA', name)
        select case (name)
        case ('INST')
            value = res%inst(index)
        case default
            call occ%error_at('PARA', 'the result stores no parameter ' // name // &
                ' (parasol stores INST)', st, STATUS_MODEL_ERROR)
        end select
    end subroutine parameter_value

    !> CHAM_NO, CARTE or CHAM_ELEM occurrence: a value of a field concept.
    subroutine test_field_occurrence(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: mesh
        type(test_check_t), allocatable :: checks(:)
        type(test_columns_t) :: cols
        real(dp) :: computed
        logical :: integers
        character(len=:), allocatable :: component
        call occ%get_concept('CHAM_GD', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            call read_checks(occ, checks, integers, st)
            if (st%failed()) return
            call mesh_of_support(p%support, mesh, st)
            if (st%failed()) then
                call relocate(occ, 'CHAM_GD', st)
                return
            end if
            component = ''
            if (occ%has('NOM_CMP')) call occ%get_text('NOM_CMP', component, st)
            if (st%failed()) return
            call add_column(cols, 'CHAM_GD', p%name)
            if (len(component) > 0) call add_column(cols, 'NOM_CMP', component)
            call test_value_in_field(ctx, occ, p%field, mesh, p%name, component, cols, &
                computed, st)
            if (st%failed()) return
            if (occ%has('VALE_ABS')) call vale_abs_column(occ, cols)
            call write_test_block(ctx, cols, checks, computed)
        class default
            call occ%error_at('CHAM_GD', 'expected a field (CREA_CHAMP), got ' // &
                p%type_name(), st)
        end select
    end subroutine test_field_occurrence

    !> The VALE_ABS column when VALE_ABS='OUI'.
    subroutine vale_abs_column(occ, cols)
        type(keyword_set_t), intent(in) :: occ
        type(test_columns_t), intent(inout) :: cols
        character(len=:), allocatable :: text
        type(status_t) :: st
        call occ%get_text('VALE_ABS', text, st)
        if (st%ok() .and. text == 'OUI') call add_column(cols, 'VALE_ABS', text)
    end subroutine vale_abs_column

    !> MAILLAGE occurrence: a count of the mesh (CARA NB_MAILLE, NB_NOEUD, NB_GROUP_MA,
    !> NB_GROUP_NO, NB_MA_GROUP_MA of NOM_GROUP_MA, NB_NO_GROUP_NO of NOM_GROUP_NO).
    subroutine test_mesh_occurrence(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: mesh
        type(test_check_t), allocatable :: checks(:)
        type(test_columns_t) :: cols
        character(len=:), allocatable :: cara, group
        integer(i4) :: g, count_value
        logical :: integers
        call occ%get_concept('MAILLAGE', p, st)
        if (st%failed()) return
        call mesh_of_support(p, mesh, st)
        if (st%failed()) then
            call relocate(occ, 'MAILLAGE', st)
            return
        end if
        call read_checks(occ, checks, integers, st)
        if (st%ok()) call occ%get_text('CARA', cara, st)
        if (st%failed()) return
        call add_column(cols, 'MAILLAGE', p%name)
        call add_column(cols, 'CARA', cara)
        group = ''
        select case (cara)
        case ('NB_MAILLE')
            count_value = mesh%n_cells
        case ('NB_NOEUD')
            count_value = mesh%n_nodes
        case ('NB_GROUP_MA')
            count_value = n_cell_groups(mesh)
        case ('NB_GROUP_NO')
            count_value = n_node_groups(mesh)
        case ('NB_MA_GROUP_MA')
            if (.not. occ%has('NOM_GROUP_MA')) then
                call occ%error_at('CARA', 'NB_MA_GROUP_MA counts the cells of a group: ' // &
                    'give NOM_GROUP_MA', st, STATUS_MODEL_ERROR)
                return
            end if
            call occ%get_text('NOM_GROUP_MA', group, st)
            if (st%ok()) g = find_cell_group(mesh, group, st)
            if (st%failed()) then
                call relocate(occ, 'NOM_GROUP_MA', st)
                return
            end if
            count_value = size(cells_of_group(mesh, g), kind=i4)
            call add_column(cols, 'NOM_GROUP_MA', group)
        case ('NB_NO_GROUP_NO')
            if (.not. occ%has('NOM_GROUP_NO')) then
                call occ%error_at('CARA', 'NB_NO_GROUP_NO counts the nodes of a group: ' // &
                    'give NOM_GROUP_NO', st, STATUS_MODEL_ERROR)
                return
            end if
            call occ%get_text('NOM_GROUP_NO', group, st)
            if (st%ok()) g = find_node_group(mesh, group, st)
            if (st%failed()) then
                call relocate(occ, 'NOM_GROUP_NO', st)
                return
            end if
            count_value = size(nodes_of_group(mesh, g), kind=i4)
            call add_column(cols, 'NOM_GROUP_NO', group)
        case default
            count_value = 0
        end select
        if (.not. integers) checks(:)%integers = .true.
        call write_test_block(ctx, cols, checks, real(count_value, dp))
    end subroutine test_mesh_occurrence

    !> The result concept given at `key` of `occ`.
    !>  res : out, points to the concept (owned by the run context)
    !>  st  : located error at `key` when the concept is not a result
    subroutine result_of_keyword(occ, key, res, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        class(result_fields_t), pointer, intent(out) :: res
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: ptr
        res => null()
        call occ%get_concept(key, ptr, st)
        if (st%failed()) return
        select type (ptr)
        class is (result_fields_t)
            res => ptr
        class default
            call occ%error_at(key, 'expected a result (evol_elas, evol_noli, evol_ther), ' // &
                'got ' // ptr%type_name(), st)
        end select
    end subroutine result_of_keyword

    !> The stored instant (1..n_stored) an occurrence asks for by INST or NUME_ORDRE; INST
    !> is matched with the second TOLE_MACHINE and CRITERE when given (Code_Aster's
    !> precision of the instant), else within RESULT_INST_PRECISION relative.
    !>  st : located error at INST or NUME_ORDRE listing what is stored
    subroutine result_index_of(occ, res, index, st)
        type(keyword_set_t), intent(in) :: occ
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(out) :: index
        type(status_t), intent(out) :: st
        real(dp) :: inst, precision
        real(dp), allocatable :: tolerances(:)
        type(string_t), allocatable :: criteria(:)
        character(len=:), allocatable :: criterion
        integer(i4) :: nume_ordre
        index = 0
        if (occ%has('INST')) then
            call occ%get_real('INST', inst, st)
            if (st%failed()) return
            precision = RESULT_INST_PRECISION
            criterion = 'RELATIF'
            if (occ%has('TOLE_MACHINE')) then
                call occ%get_reals('TOLE_MACHINE', tolerances, st)
                if (st%failed()) return
                if (size(tolerances) > 1) precision = tolerances(2)
            end if
            if (occ%has('CRITERE')) then
                call occ%get_texts('CRITERE', criteria, st)
                if (st%failed()) return
                if (size(criteria) > 1) criterion = criteria(2)%s
            end if
            call result_find(res, index, st, inst=inst, precision=precision, &
                criterion=criterion)
            if (st%failed()) call relocate(occ, 'INST', st)
        else
            call occ%get_int('NUME_ORDRE', nume_ordre, st)
            if (st%failed()) return
            call result_find(res, index, st, nume_ordre=nume_ordre)
            if (st%failed()) call relocate(occ, 'NUME_ORDRE', st)
        end if
    end subroutine result_index_of

    !> Value of one component of a nodal field of an analysis at one stored instant.
    !>  res       : in, the result
    !>  field     : in, DEPL, FORC_NODA or REAC_NODA
    !>  index     : in, stored instant, 1..res%n_stored
    !>  node      : in, node number of res%mesh
    !>  component : in, DX .. DRZ
    !>  value     : out, the value (0 on error)
    !>  st        : STATUS_MODEL_ERROR naming the node when it has no such component, the
    !>              field is unknown or index/node are out of range
    subroutine test_resu_value(res, field, index, node, component, value, st)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field, component
        integer(i4), intent(in) :: index, node
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        value = 0.0_dp
        if (index < 1 .or. index > res%n_stored) then
            call set_error(st, STATUS_MODEL_ERROR, 'instant ' // to_text(index) // &
                           ' is not stored (the result holds ' // to_text(res%n_stored) // ')')
            return
        end if
        if (node < 1 .or. node > res%mesh%n_nodes .or. node > res%dofs%n_nodes) then
            call set_error(st, STATUS_MODEL_ERROR, 'node number ' // to_text(node) // &
                           ' is not in the mesh of the result')
            return
        end if
        call result_node_value(res, field, index, node, component, value, st)
        if (st%failed()) st%message = 'node ' // trim(node_label(res, node)) // ': ' // &
            st%message
    end subroutine test_resu_value

    function node_label(res, node) result(text)
        use mesh_types, only: node_name
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: node
        character(len=:), allocatable :: text
        text = node_name(res%mesh, node)
    end function node_label

    !> The one node of GROUP_NO `group` (test_resu_checks%single_node).
    subroutine test_resu_single_node(mesh, group, node, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: node
        type(status_t), intent(out) :: st
        call single_node(mesh, group, node, st)
    end subroutine test_resu_single_node

    !> The one cell of GROUP_MA `group` (test_resu_checks%single_cell).
    subroutine test_resu_single_cell(mesh, group, cell, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: cell
        type(status_t), intent(out) :: st
        call single_cell(mesh, group, cell, st)
    end subroutine test_resu_single_cell

end module test_resu_command
