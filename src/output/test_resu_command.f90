!> TEST_RESU: checks values of a result (evol_elas, evol_noli) against the deck's
!> non-regression value VALE_CALC and, with REFERENCE, against VALE_REFE (listings.md,
!> "TEST_RESU blocks"). Each RESU occurrence writes one block to the `.resu` (identification
!> lines, table header, one check line per check), echoes each check line in compact form to
!> the `.mess` and counts it in the run context (NOOK makes the run exit with status 2).
!>
!> The tested instant is found by NUME_ORDRE, or by INST within RESULT_INST_PRECISION
!> (relative, absolute below |INST| = 1: analysis_result%result_find). A nodal field (DEPL,
!> FORC_NODA, REAC_NODA) is read at NOEUD, or GROUP_NO when that group holds exactly one
!> node; an element field (SIEF_ELGA, VARI_ELGA of the DIS_CHOC springs) at POINT of MAILLE,
!> or of GROUP_MA when that group holds exactly one cell.
!>
!> A listing never contains NaN or Inf: the spellings of non-finite numbers produced by the
!> formatting layer (`NaN`, `+Inf`, `-Inf`) are replaced by the words NON_FINI, +INFINI and
!> -INFINI (listing_safe_text), which no reader takes for a number.
module test_resu_command
    use kinds, only: dp, i4
    use status, only: status_t, set_error, clear_status, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node, find_node_group, nodes_of_group, node_name, &
        find_cell, find_cell_group, cells_of_group
    use analysis_result, only: result_concept_t, result_find, result_node_value, &
        result_cell_value, is_cell_field
    use element_spring_fields, only: SPRING_POINTS
    use test_resu_format, only: test_resu_block_lines
    implicit none
    private

    !> Words written instead of the non-finite spellings NaN, +Inf, -Inf.
    character(len=*), parameter, public :: LISTING_NOT_FINITE = 'NON_FINI'
    character(len=*), parameter, public :: LISTING_PLUS_INFINITE = '+INFINI'
    character(len=*), parameter, public :: LISTING_MINUS_INFINITE = '-INFINI'

    public :: run_test_resu, test_resu_value, test_resu_single_node, listing_safe_text, &
        compact_text, result_of_keyword, result_index_of, relocate, test_resu_single_cell

contains

    !> Handler of TEST_RESU (doc/architecture.md "Writing a command handler").
    !>  st : located errors at the keyword at fault (RESULTAT of another type, INST or
    !>       NUME_ORDRE not stored, GROUP_NO not holding exactly one node, unknown NOEUD,
    !>       component absent at the node, REFERENCE without VALE_REFE or the reverse)
    subroutine run_test_resu(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer :: k
        if (allocated(result)) deallocate (result)     ! TEST_RESU has no result
        do k = 1, cmd%count('RESU')
            call test_one_occurrence(ctx, cmd%occurrence('RESU', k), st)
            if (st%failed()) return
        end do
    end subroutine run_test_resu

    !> One RESU occurrence: find the value, write the block, count the checks.
    subroutine test_one_occurrence(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        type(result_concept_t), pointer :: res
        integer(i4) :: index, node
        real(dp) :: computed
        character(len=:), allocatable :: field, component, location_kind, location_name
        type(string_t), allocatable :: lines(:)
        call result_of_keyword(occ, 'RESULTAT', res, st)
        if (st%failed()) return
        call result_index_of(occ, res, index, st)
        if (st%failed()) return
        call occ%get_text('NOM_CHAM', field, st)
        if (st%failed()) return
        call occ%get_text('NOM_CMP', component, st)
        if (st%failed()) return
        location_kind = 'NOEUD'
        if (occ%has('GROUP_NO')) location_kind = 'GROUP_NO'
        if (occ%has('GROUP_MA')) location_kind = 'GROUP_MA'
        if (occ%has('MAILLE')) location_kind = 'MAILLE'
        call occ%get_text(location_kind, location_name, st)
        if (st%failed()) return
        if (is_cell_field(field)) then
            call test_cell_occurrence(ctx, occ, res, index, field, component, location_kind, &
                                      location_name, st)
            return
        end if
        if (location_kind == 'GROUP_MA' .or. location_kind == 'MAILLE') then
            call occ%error_at(location_kind, field // ' is a nodal field: give GROUP_NO ' // &
                'or NOEUD (GROUP_MA and MAILLE go with SIEF_ELGA and VARI_ELGA)', st)
            return
        end if
        if (occ%has('POINT')) then
            call occ%error_at('POINT', 'POINT goes with the element fields SIEF_ELGA and ' // &
                'VARI_ELGA; ' // field // ' is read at a node', st)
            return
        end if
        if (location_kind == 'GROUP_NO') then
            call test_resu_single_node(res%mesh, location_name, node, st)
        else
            node = find_node(res%mesh, location_name, st)
        end if
        if (st%failed()) then
            call relocate(occ, location_kind, st)
            return
        end if
        call test_resu_value(res, field, index, node, component, computed, st)
        if (st%failed()) then
            call relocate(occ, 'NOM_CMP', st)
            return
        end if
        call block_lines(occ, res, index, field, component, location_kind, location_name, &
                         computed, lines, st)
        if (st%failed()) return
        call write_block(ctx, lines)
    end subroutine test_one_occurrence

    !> An element field (SIEF_ELGA, VARI_ELGA) at POINT of a cell (MAILLE, or GROUP_MA of one
    !> cell).
    subroutine test_cell_occurrence(ctx, occ, res, stored, field, component, location_kind, &
                                    location_name, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: stored
        character(len=*), intent(in) :: field, component, location_kind, location_name
        type(status_t), intent(out) :: st
        integer(i4) :: cell, point
        real(dp) :: computed
        type(string_t), allocatable :: lines(:)
        if (location_kind == 'GROUP_NO' .or. location_kind == 'NOEUD') then
            call occ%error_at(location_kind, field // ' is an element field: give ' // &
                'GROUP_MA (a group of one cell) or MAILLE, and POINT', st)
            return
        end if
        if (.not. occ%has('POINT')) then
            call occ%error_at('NOM_CHAM', field // ' is read at a point: give POINT (1 or ' // &
                '2, the nodes of a SEG2 spring)', st)
            return
        end if
        call occ%get_int('POINT', point, st)
        if (st%failed()) return
        if (point < 1 .or. point > SPRING_POINTS) then
            call occ%error_at('POINT', 'a SEG2 spring has points 1 and 2 (its Gauss points ' // &
                'sit at its nodes), not ' // to_text(point), st)
            return
        end if
        if (location_kind == 'GROUP_MA') then
            call test_resu_single_cell(res%mesh, location_name, cell, st)
        else
            cell = find_cell(res%mesh, location_name, st)
        end if
        if (st%failed()) then
            call relocate(occ, location_kind, st)
            return
        end if
        call result_cell_value(res, field, stored, cell, point, component, computed, st)
        if (st%failed()) then
            if (any(res%spring_cell == cell)) then
                call relocate(occ, 'NOM_CMP', st)      ! a component the field lacks
            else
                call relocate(occ, location_kind, st)  ! no spring there
            end if
            return
        end if
        call block_lines(occ, res, stored, field, component, location_kind, location_name, &
                         computed, lines, st, point)
        if (st%failed()) return
        call write_block(ctx, lines)
    end subroutine test_cell_occurrence

    !> The one cell of GROUP_MA `group`.
    !>  st : STATUS_MODEL_ERROR when the group does not exist (with a did-you-mean) or does
    !>       not hold exactly one cell (naming the group and its size)
    subroutine test_resu_single_cell(mesh, group, cell, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: cell
        type(status_t), intent(out) :: st
        integer(i4) :: g
        integer(i4), allocatable :: members(:)
        cell = 0
        g = find_cell_group(mesh, group, st)
        if (st%failed()) return
        members = cells_of_group(mesh, g)
        if (size(members) /= 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'GROUP_MA ' // group // ' holds ' // &
                           to_text(size(members, kind=i4)) // &
                           ' cells; TEST_RESU needs a group of exactly one cell (or MAILLE)')
            return
        end if
        cell = members(1)
    end subroutine test_resu_single_cell

    !> The TEST_RESU block of one occurrence, checks counted by the caller from the lines.
    !>  point : in, optional, POINT of an element field (a column of the block)
    subroutine block_lines(occ, res, index, field, component, location_kind, location_name, &
                           computed, lines, st, point)
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: index
        character(len=*), intent(in) :: field, component, location_kind, location_name
        real(dp), intent(in) :: computed
        type(string_t), allocatable, intent(out) :: lines(:)
        type(status_t), intent(out) :: st
        integer(i4), intent(in), optional :: point
        real(dp) :: vale_calc, tole_machine, vale_refe, precision, inst
        character(len=:), allocatable :: criterion, reference, legend, result_name
        integer :: n_ok, n_nook
        call occ%get_real('VALE_CALC', vale_calc, st)
        if (st%ok()) call occ%get_real('TOLE_MACHINE', tole_machine, st)
        if (st%ok()) call occ%get_real('PRECISION', precision, st)
        if (st%ok()) call occ%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        if (tole_machine < 0.0_dp .or. precision < 0.0_dp) then
            call occ%error_at(trim(merge('TOLE_MACHINE', 'PRECISION   ', &
                                         tole_machine < 0.0_dp)), 'a tolerance must be >= 0', st)
            return
        end if
        if (occ%has('REFERENCE') .neqv. occ%has('VALE_REFE')) then
            call occ%error_at(merge('REFERENCE', 'VALE_REFE', occ%has('REFERENCE')), &
                              'REFERENCE and VALE_REFE go together (give both or neither)', st)
            return
        end if
        legend = ''
        if (occ%has('LEGENDE')) call occ%get_text('LEGENDE', legend, st)
        if (st%failed()) return
        result_name = res%name
        n_ok = 0
        n_nook = 0
        inst = res%inst(index)
        if (occ%has('REFERENCE')) then
            call occ%get_text('REFERENCE', reference, st)
            if (st%ok()) call occ%get_real('VALE_REFE', vale_refe, st)
            if (st%failed()) return
            if (occ%has('INST')) then
                call test_resu_block_lines(result_name, field, component, location_kind, &
                    location_name, vale_calc, computed, tole_machine, criterion, lines, n_ok, &
                    n_nook, nume_ordre=int(res%nume_ordre(index)), inst=inst, &
                    reference_kind=reference, vale_refe=vale_refe, precision=precision, &
                    legend=legend, point=point)
            else
                call test_resu_block_lines(result_name, field, component, location_kind, &
                    location_name, vale_calc, computed, tole_machine, criterion, lines, n_ok, &
                    n_nook, nume_ordre=int(res%nume_ordre(index)), reference_kind=reference, &
                    vale_refe=vale_refe, precision=precision, legend=legend, point=point)
            end if
        else if (occ%has('INST')) then
            call test_resu_block_lines(result_name, field, component, location_kind, &
                location_name, vale_calc, computed, tole_machine, criterion, lines, n_ok, &
                n_nook, nume_ordre=int(res%nume_ordre(index)), inst=inst, point=point)
        else
            call test_resu_block_lines(result_name, field, component, location_kind, &
                location_name, vale_calc, computed, tole_machine, criterion, lines, n_ok, &
                n_nook, nume_ordre=int(res%nume_ordre(index)), point=point)
        end if
    end subroutine block_lines

    !> Writes a block to the .resu, each check line compacted to the .mess, and counts the
    !> check lines (lines 4 and after start with ' OK ' or 'NOOK').
    subroutine write_block(ctx, lines)
        type(run_context_t), intent(inout) :: ctx
        type(string_t), intent(in) :: lines(:)
        integer :: k
        character(len=:), allocatable :: id
        do k = 1, size(lines)
            call ctx%write_resu(listing_safe_text(lines(k)%s))
        end do
        id = compact_text(lines(2)%s)
        do k = 4, size(lines)
            call ctx%count_test(lines(k)%s(1:4) == ' OK ')
            call ctx%write_mess('    TEST_RESU ' // id // ': ' // &
                                listing_safe_text(compact_text(lines(k)%s)))
        end do
    end subroutine write_block

    !> The result concept given at `key` of `occ`.
    !>  res : out, points to the concept (owned by the run context)
    !>  st  : located error at `key` when the concept is not a result (evol_elas, evol_noli)
    subroutine result_of_keyword(occ, key, res, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(result_concept_t), pointer, intent(out) :: res
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: ptr
        res => null()
        call occ%get_concept(key, ptr, st)
        if (st%failed()) return
        select type (ptr)
        type is (result_concept_t)
            res => ptr
        class default
            call occ%error_at(key, 'expected a result (evol_elas or evol_noli), got ' // &
                              ptr%type_name(), st)
        end select
    end subroutine result_of_keyword

    !> The stored instant (1..n_stored) an occurrence asks for by INST or NUME_ORDRE.
    !>  st : located error at INST or NUME_ORDRE listing what is stored
    subroutine result_index_of(occ, res, index, st)
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(out) :: index
        type(status_t), intent(out) :: st
        real(dp) :: inst
        integer(i4) :: nume_ordre
        index = 0
        if (occ%has('INST')) then
            call occ%get_real('INST', inst, st)
            if (st%failed()) return
            call result_find(res, index, st, inst=inst)
            if (st%failed()) call relocate(occ, 'INST', st)
        else
            call occ%get_int('NUME_ORDRE', nume_ordre, st)
            if (st%failed()) return
            call result_find(res, index, st, nume_ordre=nume_ordre)
            if (st%failed()) call relocate(occ, 'NUME_ORDRE', st)
        end if
    end subroutine result_index_of

    !> Value of one component of a nodal field at one stored instant.
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
        if (st%failed()) st%message = 'node ' // node_name(res%mesh, node) // ': ' // &
                                      st%message
    end subroutine test_resu_value

    !> The one node of GROUP_NO `group`.
    !>  st : STATUS_MODEL_ERROR when the group does not exist (with a did-you-mean) or does
    !>       not hold exactly one node (naming the group and its size)
    subroutine test_resu_single_node(mesh, group, node, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: node
        type(status_t), intent(out) :: st
        integer(i4) :: g
        integer(i4), allocatable :: members(:)
        node = 0
        g = find_node_group(mesh, group, st)
        if (st%failed()) return
        members = nodes_of_group(mesh, g)
        if (size(members) /= 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'GROUP_NO ' // group // ' holds ' // &
                           to_text(size(members, kind=i4)) // &
                           ' nodes; TEST_RESU needs a group of exactly one node (or NOEUD)')
            return
        end if
        node = members(1)
    end subroutine test_resu_single_node

    !> Locates a failed status (from a layer that does not know the deck) at `key` of `occ`,
    !> keeping its message; the category becomes STATUS_MODEL_ERROR.
    subroutine relocate(occ, key, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message
        message = st%message
        call clear_status(st)
        call occ%error_at(key, message, st, STATUS_MODEL_ERROR)
    end subroutine relocate

    !> `text` with the non-finite spellings NaN, +Inf, -Inf (whole tokens, optionally
    !> followed by %) replaced by NON_FINI, +INFINI, -INFINI.
    pure function listing_safe_text(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: i, j
        character(len=:), allocatable :: token, core
        out = ''
        i = 1
        do while (i <= len(text))
            if (text(i:i) == ' ') then
                out = out // ' '
                i = i + 1
                cycle
            end if
            j = i
            do while (j < len(text))
                if (text(j + 1:j + 1) == ' ') exit
                j = j + 1
            end do
            token = text(i:j)
            core = token
            if (len(core) > 1) then
                if (core(len(core):) == '%') core = core(1:len(core) - 1)
            end if
            select case (core)
            case ('NaN')
                token = LISTING_NOT_FINITE // token(len(core) + 1:)
            case ('+Inf', 'Inf')
                token = LISTING_PLUS_INFINITE // token(len(core) + 1:)
            case ('-Inf')
                token = LISTING_MINUS_INFINITE // token(len(core) + 1:)
            end select
            out = out // token
            i = j + 1
        end do
    end function listing_safe_text

    !> `text` without leading/trailing blanks and with runs of blanks reduced to one (the
    !> compact echo of a listing line in the .mess).
    pure function compact_text(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: i
        out = ''
        do i = 1, len_trim(text)
            if (text(i:i) == ' ') then
                if (len(out) == 0) cycle
                if (out(len(out):) == ' ') cycle
            end if
            out = out // text(i:i)
        end do
    end function compact_text

end module test_resu_command
