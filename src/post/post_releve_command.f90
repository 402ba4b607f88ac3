!> POST_RELEVE_T (U4.81.21): a table of values of fields along a list of nodes, as Code_
!> Aster's op0051 builds it (doc/tables.md, "POST_RELEVE_T"). Each ACTION occurrence reads
!> a field — of RESULTAT (NOM_CHAM at TOUT_ORDRE / NUME_ORDRE / INST / LIST_INST, every
!> stored instant by default) or CHAM_GD — nodal (NOEU) or at the nodes of the cells (ELNO),
!> at the nodes of NOEUD then of each GROUP_NO (in their order, each node once; for a nodal
!> field only the nodes holding a component asked for), and writes:
!>  EXTRACTION  a row per node (MOYE_NOEUD='NON': per node and cell holding it, with
!>              MAILLE): INTITULE, NOEUD, RESU, NOM_CHAM, NUME_ORDRE, INST (or CHAM_GD),
!>              ABSC_CURV (the length along the nodes in turn), COOR_X, COOR_Y, COOR_Z and
!>              the quantities;
!>  MOYENNE     six rows (QUANTITE MOMENT_0, MOMENT_1, MINIMUM, MAXIMUM, MOYE_INT,
!>              MOYE_EXT: the mean and linear moment of each quantity along ABSC_CURV);
!>  RESULTANTE  one row of the sums of the components over the nodes (with MOMENT and
!>              POINT: RESULT_X .. MOMENT_Z, the moment about POINT);
!>  MOYENNE_ARITH  per component, its sum over the nodes divided by their number (CMP,
!>              MOYENNE); EXTREMA  the MAX, MIN, MAXI_ABS, MINI_ABS of the components over
!>              the nodes (EXTREMA, NOEUD (its number, as Code_Aster writes it), CMP, VALE).
!> An ELNO value at a node is the mean of the values of the cells holding it (MOYE_NOEUD
!> 'OUI'), the cells being those around the listed nodes that hold a component asked for
!> (GROUP_MA / MAILLE restrict them); cells with sub-points (plate layers) are left out, as
!> Code_Aster leaves them out. A component a node lacks counts 0, as in Code_Aster.
!> The quantities: the components (NOM_CMP, TOUT_CMP), in REPERE GLOBAL, UTILISATEUR
!> (ANGL_NAUT) and CYLINDRIQUE (ORIGINE, AXE_Z) — displacement-like vectors (DX DY DZ,
!> DRX DRY DRZ) of a DEPL_R field and tensors of SIEF_R / EPSI_R fields turned —, LOCAL
!> (the tangent and normal of the node path) and POLAIRE (radial, -orthoradial), in the
!> plane, on nodes of one z; INVARIANT (VMIS, TRESCA, TRACE, DETER) and ELEM_PRINCIPAUX
!> (PRIN_1..3 increasing, VECT_i_X..Z) of a stress or strain tensor; TRAC_DIR (S d, or v.d)
!> and TRAC_NOR (S n, v.n, n the path's normal in the plane).
!> The table's columns are declared first, in Code_Aster's order (rvpara), over all the
!> occurrences; a column no row fills stays empty (IMPR_TABLE leaves it out). Not built,
!> each an error saying so: complex fields, modal and harmonic results (NUME_MODE, FREQ,
!> NOM_CAS, NOEUD_CMP), VECT_Y (3D local frames), internal variables of ELNO fields, EFGE-
!> type plate resultants in LOCAL / POLAIRE or with INVARIANT.
module post_releve_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, real_e13
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use progress, only: wall_seconds
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use deck_catalog, only: split_words
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node, find_node_group, nodes_of_group, node_name
    use field_types, only: field_t, FIELD_NOEU, FIELD_ELNO, field_component, field_position, &
        field_location_name
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use result_instants, only: selected_instants
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_find_column, table_set_int, table_set_real, table_set_text, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT, table_text_width_for, table_entity_label
    use table_keywords, only: relocate_at, warn_at
    use crea_table_command, only: result_of_occurrence, mesh_of_support
    use crea_champ_command, only: selected_nodes, selected_cells
    use releve_frames, only: path_abscissae, plane_local_frames, polar_frame, &
        cylindrical_frame, user_frame, rotate_vector, rotate_tensor, tensor_invariants, &
        principal_stresses, path_statistics, KIND_VECTOR, KIND_TENSOR, KIND_OTHER, &
        VECTOR_CMPS, TENSOR_SLOT_NAMES, value_kind, tensor_row, turned_value, traction
    implicit none
    private

    public :: run_post_releve_t

    !> Quantities (Code_Aster's rvcpnc QUANT).
    integer, parameter :: Q_COMPONENTS = 1, Q_INVARIANTS = 2, Q_PRINCIPAL = 3, &
        Q_TRAC_NOR = 4, Q_TRAC_DIR = 5, Q_SUM = 6
    !> Largest magnitude of a value turned, summed or averaged (sums of a few thousand
    !> products with lengths up to MAX_LENGTH stay finite); DETER cubes values, 1e100.
    real(dp), parameter :: VALUE_LIMIT = 1.0e200_dp, CUBE_LIMIT = 1.0e100_dp

    !> One ACTION occurrence, read.
    type :: action_t
        character(len=:), allocatable :: label           !< INTITULE (16 characters)
        character(len=:), allocatable :: operation       !< the first OPERATION
        logical :: extraction = .false., mean = .false.
        integer :: quantity = Q_COMPONENTS
        type(string_t), allocatable :: asked(:)          !< NOM_CMP, RESULTANTE(+MOMENT)
        logical :: all_components = .false.             !< TOUT_CMP
        character(len=:), allocatable :: frame           !< REPERE
        real(dp) :: angles(3) = 0.0_dp, origin(3) = 0.0_dp, axis(3) = 0.0_dp
        real(dp) :: direction(3) = 0.0_dp, point(3) = 0.0_dp
        integer :: n_resultant = 0, n_moment = 0
        logical :: average = .true.                      !< MOYE_NOEUD
    end type action_t

    !> A field read, with what the rows say about it.
    type :: source_t
        type(field_t), pointer :: f => null()
        character(len=:), allocatable :: resu, nom_cham, cham_gd
        integer :: nume_ordre = 0
        real(dp) :: inst = 0.0_dp
        logical :: from_result = .false.
    end type source_t

    !> Where an occurrence's fields come from.
    type :: provider_t
        class(result_fields_t), pointer :: res => null()
        type(field_concept_t), pointer :: cham => null()
        type(mesh_t), pointer :: mesh => null()
        integer, allocatable :: indices(:)
        character(len=:), allocatable :: nom_cham
    end type provider_t

    !> The values at the points of the path: per point (a node, or a node and one of its
    !> cells), the named quantities.
    type :: path_values_t
        integer, allocatable :: node(:), cell(:)          !< cell 0: averaged at the node
        type(string_t), allocatable :: names(:)
        real(dp), allocatable :: v(:, :)                  !< (names, points)
    end type path_values_t

contains

    !> Handler of POST_RELEVE_T.
    subroutine run_post_releve_t(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), allocatable :: t
        integer :: k
        real(dp) :: start
        character(len=32) :: seconds
        start = wall_seconds()
        allocate (t)
        call table_init(t)
        call declare_columns(cmd, t, st)
        if (st%failed()) return
        do k = 1, cmd%count('ACTION')
            call run_action(ctx, cmd%occurrence('ACTION', k), t, st)
            if (st%failed()) return
        end do
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', t%title, st)
            if (st%failed()) return
        end if
        write (seconds, '(f0.3)') wall_seconds() - start
        call ctx%write_mess('    POST_RELEVE_T: ' // to_text(int(t%n_rows, i4)) // ' rows, ' // &
            to_text(int(t%n_columns, i4)) // ' columns, ' // trim(seconds) // ' s')
        call move_alloc(t, result)
    end subroutine run_post_releve_t

    ! ---- the columns -----------------------------------------------------------------

    !> The columns Code_Aster's rvpara declares, in its order, from every occurrence.
    subroutine declare_columns(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: components(:), ops(:), names(:)
        logical :: any_result, any_field, nodes, per_cell, absc, invariants, principal, &
            moments, trac_nor, trac_dir, means, extrema, arith, listed
        integer :: k, j
        any_result = .false.; any_field = .false.; nodes = .false.; per_cell = .false.
        absc = .false.; invariants = .false.; principal = .false.; moments = .false.
        trac_nor = .false.; trac_dir = .false.; means = .false.; extrema = .false.
        arith = .false.; listed = .false.
        allocate (components(0))
        do k = 1, cmd%count('ACTION')
            occ = cmd%occurrence('ACTION', k)
            call occ%get_texts('OPERATION', ops, st)
            if (st%failed()) return
            if (occ%has('RESULTAT')) any_result = .true.
            if (occ%has('CHAM_GD')) any_field = .true.
            if (ops(1)%s == 'EXTREMA') extrema = .true.
            if (ops(1)%s == 'MOYENNE_ARITH') arith = .true.
            if (ops(1)%s == 'EXTREMA' .or. ops(1)%s == 'MOYENNE_ARITH') cycle
            listed = .true.
            if (any(names_equal(ops, 'MOYENNE'))) means = .true.
            if (occ%has('TOUT_CMP')) then
                call field_components_of(occ, names, st)
                if (st%failed()) return
                call add_names(components, names)
            end if
            if (occ%has('NOM_CMP') .and. .not. (occ%has('TRAC_NOR') .or. &
                occ%has('TRAC_DIR'))) then
                call occ%get_texts('NOM_CMP', names, st)
                if (st%failed()) return
                call add_names(components, names)
            end if
            if (occ%has('TRAC_NOR')) trac_nor = .true.
            if (occ%has('TRAC_DIR')) trac_dir = .true.
            if (occ%has('ELEM_PRINCIPAUX')) principal = .true.
            if (occ%has('RESULTANTE') .and. occ%has('MOMENT')) moments = .true.
            if (occ%has('RESULTANTE') .and. .not. occ%has('MOMENT')) then
                call occ%get_texts('RESULTANTE', names, st)
                if (st%failed()) return
                call add_names(components, names)
            end if
            if (any(names_equal(ops, 'EXTRACTION'))) then
                if (occ%has('INVARIANT')) invariants = .true.
                if (.not. occ%has('RESULTANTE')) then
                    absc = .true.
                    if (occ%has('NOEUD') .or. occ%has('GROUP_NO')) nodes = .true.
                end if
            end if
            if (occ%given('MOYE_NOEUD')) then
                call occ%get_texts('MOYE_NOEUD', names, st)
                if (st%failed()) return
                if (names(1)%s == 'NON') per_cell = .true.
            end if
        end do
        call column('INTITULE', TABLE_TEXT, 16)
        if (listed .and. nodes) call column('NOEUD', TABLE_TEXT, 8)
        if (any_field) call column('CHAM_GD', TABLE_TEXT, 8)
        if (any_result) then
            call column('RESU', TABLE_TEXT, 8)
            call column('NOM_CHAM', TABLE_TEXT, 16)
            call column('NUME_ORDRE', TABLE_INT, 0)
            call column('INST', TABLE_REAL, 0)
        end if
        if (listed .and. per_cell) call column('MAILLE', TABLE_TEXT, 8)
        if (listed .and. absc) then
            call column('ABSC_CURV', TABLE_REAL, 0)
            call column('COOR_X', TABLE_REAL, 0)
            call column('COOR_Y', TABLE_REAL, 0)
            call column('COOR_Z', TABLE_REAL, 0)
        end if
        if (listed) then
            do j = 1, size(components)
                call column(components(j)%s, TABLE_REAL, 0)
            end do
        end if
        if (listed .and. invariants) call columns('VMIS TRESCA TRACE DETER')
        if (listed .and. principal) call columns('PRIN_1 PRIN_2 PRIN_3 VECT_1_X VECT_1_Y ' // &
            'VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y VECT_3_Z')
        if (listed .and. moments) call columns('RESULT_X RESULT_Y RESULT_Z MOMENT_X ' // &
            'MOMENT_Y MOMENT_Z')
        if (listed .and. trac_nor) call columns('TRAC_NOR TR_NOR_1 TR_NOR_2 TR_NOR_3')
        if (listed .and. trac_dir) call columns('TRAC_DIR TR_DIR_1 TR_DIR_2 TR_DIR_3')
        if (listed .and. means) call column('QUANTITE', TABLE_TEXT, 16)
        if (extrema) then
            call column('EXTREMA', TABLE_TEXT, 8)
            call column('MAILLE', TABLE_TEXT, 8)
            call column('NOEUD', TABLE_TEXT, 8)
            call column('CMP', TABLE_TEXT, 8)
            call column('VALE', TABLE_REAL, 0)
        end if
        if (arith) then
            call column('CMP', TABLE_TEXT, 8)
            call column('MOYENNE', TABLE_REAL, 0)
        end if
    contains
        subroutine column(name, kind, width)
            character(len=*), intent(in) :: name
            integer, intent(in) :: kind, width
            integer :: c
            if (st%failed()) return
            if (table_find_column(t, name) > 0) return
            if (kind == TABLE_TEXT) then
                call table_add_column(t, name, kind, c, st, width)
            else
                call table_add_column(t, name, kind, c, st)
            end if
        end subroutine column

        subroutine columns(list)
            character(len=*), intent(in) :: list
            type(string_t), allocatable :: words(:)
            integer :: w
            words = split_names(list)
            do w = 1, size(words)
                call column(words(w)%s, TABLE_REAL, 0)
            end do
        end subroutine columns
    end subroutine declare_columns

    !> Appends the names not yet in `list`.
    subroutine add_names(list, names)
        type(string_t), allocatable, intent(inout) :: list(:)
        type(string_t), intent(in) :: names(:)
        integer :: k, j
        logical :: seen
        do k = 1, size(names)
            seen = .false.
            do j = 1, size(list)
                if (list(j)%s == names(k)%s) seen = .true.
            end do
            if (.not. seen) list = [list, names(k)]
        end do
    end subroutine add_names

    !> TOUT_CMP's components: those the field holds (anywhere), in its quantity's order,
    !> at the first instant the occurrence reads.
    subroutine field_components_of(occ, names, st)
        type(keyword_set_t), intent(in) :: occ
        type(string_t), allocatable, intent(out) :: names(:)
        type(status_t), intent(inout) :: st
        type(provider_t) :: p
        type(source_t) :: src
        allocate (names(0))
        call open_provider(occ, p, st)
        if (st%failed()) return
        if (size(p%indices) == 0) return
        call fetch_field(occ, p, 1, src, st)
        if (st%failed()) return
        names = held_components(src%f)
    end subroutine field_components_of

    !> The components a field holds at some node or cell, in its quantity's order.
    function held_components(f) result(names)
        type(field_t), intent(in) :: f
        type(string_t), allocatable :: names(:)
        logical, allocatable :: held(:)
        integer :: k, c
        allocate (held(size(f%components)), source=.false.)
        if (f%location == FIELD_NOEU) then
            do k = 1, size(f%components)
                held(k) = any(f%node_has(k, :))
            end do
        else
            do c = 1, f%n_cells
                if (f%n_points(c) == 0) cycle
                held(f%sets(f%cell_set(c))%cmp) = .true.
            end do
        end if
        allocate (names(0))
        do k = 1, size(f%components)
            if (held(k)) names = [names, f%components(k)]
        end do
    end function held_components

    ! ---- the fields an occurrence reads ------------------------------------------------

    !> RESULTAT (NOM_CHAM, the instants) or CHAM_GD, and the mesh.
    subroutine open_provider(occ, p, st)
        type(keyword_set_t), intent(in) :: occ
        type(provider_t), intent(out) :: p
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: ptr
        character(len=*), parameter :: MODAL = 'LIST_ORDRE NUME_MODE LIST_MODE FREQ ' // &
            'LIST_FREQ NOM_CAS NOEUD_CMP'
        type(string_t), allocatable :: keys(:)
        logical :: by_inst
        integer :: k
        keys = split_names(MODAL)
        do k = 1, size(keys)
            if (occ%has(keys(k)%s)) then
                call occ%error_at(keys(k)%s, 'modal, harmonic and multiple-load ' // &
                    'results are not built by parasol: select the fields by TOUT_ORDRE, ' // &
                    'NUME_ORDRE, INST or LIST_INST', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
        end do
        if (occ%has('RESULTAT')) then
            call result_of_occurrence(occ, p%res, st)
            if (st%failed()) return
            if (.not. occ%has('NOM_CHAM')) then
                call occ%error_at('RESULTAT', 'give NOM_CHAM, the field of the result to ' // &
                    'read', st)
                return
            end if
            call occ%get_text('NOM_CHAM', p%nom_cham, st)
            if (st%ok()) call selected_instants(occ, p%res, p%indices, by_inst, st)
            if (st%failed()) return
            call result_mesh(p%res, p%mesh, st)
            if (st%failed()) call relocate_at(occ, 'RESULTAT', st)
        else
            call occ%get_concept('CHAM_GD', ptr, st)
            if (st%failed()) return
            select type (ptr)
            type is (field_concept_t)
                p%cham => ptr
                call mesh_of_support(ptr, p%mesh, st)
                if (st%failed()) call relocate_at(occ, 'CHAM_GD', st)
            class default
                call occ%error_at('CHAM_GD', 'expected a field (cham_no or cham_elem), ' // &
                    'got ' // ptr%type_name(), st)
            end select
            p%indices = [0]
        end if
    end subroutine open_provider

    !> The k-th field of the occurrence.
    subroutine fetch_field(occ, p, k, src, st)
        type(keyword_set_t), intent(in) :: occ
        type(provider_t), intent(inout) :: p
        integer, intent(in) :: k
        type(source_t), intent(out) :: src
        type(status_t), intent(inout) :: st
        if (associated(p%res)) then
            call result_field_at(p%res, int(p%indices(k), i4), p%nom_cham, src%f, st)
            if (st%failed()) then
                call relocate_at(occ, 'NOM_CHAM', st)
                return
            end if
            src%from_result = .true.
            src%resu = p%res%name
            src%nom_cham = p%nom_cham
            src%nume_ordre = p%res%nume_ordre(p%indices(k))
            src%inst = p%res%inst(p%indices(k))
        else
            src%f => p%cham%field
            src%cham_gd = p%cham%name
        end if
    end subroutine fetch_field

    !> The name of the field read, for messages.
    function field_label(src) result(text)
        type(source_t), intent(in) :: src
        character(len=:), allocatable :: text
        if (src%from_result) then
            text = 'field ' // src%nom_cham // ' of ' // src%resu // ' (NUME_ORDRE ' // &
                to_text(int(src%nume_ordre, i4)) // ')'
        else
            text = 'field ' // src%cham_gd
        end if
    end function field_label

    !> The key naming the field (for located errors).
    function field_key(src) result(key)
        type(source_t), intent(in) :: src
        character(len=:), allocatable :: key
        key = 'CHAM_GD'
        if (src%from_result) key = 'NOM_CHAM'
    end function field_key

    ! ---- one occurrence ------------------------------------------------------------------

    !> One ACTION occurrence: its fields, each turned into rows.
    subroutine run_action(ctx, occ, t, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(action_t) :: act
        type(provider_t) :: p
        type(source_t) :: src
        integer :: k
        call read_action(occ, act, st)
        if (st%ok()) call open_provider(occ, p, st)
        if (st%failed()) return
        do k = 1, size(p%indices)
            call fetch_field(occ, p, k, src, st)
            if (st%failed()) return
            select case (act%operation)
            case ('EXTREMA')
                call extrema_rows(occ, act, src, p%mesh, t, st)
            case ('MOYENNE_ARITH')
                call arithmetic_rows(occ, act, src, p%mesh, t, st)
            case default
                call path_rows(ctx, occ, act, src, p%mesh, t, st)
            end select
            if (st%failed()) return
        end do
    end subroutine run_action

    !> Reads and checks an occurrence (the rules of Code_Aster's blocks).
    subroutine read_action(occ, act, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(out) :: act
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: list(:), names(:), more(:)
        real(dp), allocatable :: values(:)
        character(len=:), allocatable :: text
        integer :: n
        call occ%get_texts('OPERATION', list, st)
        if (st%ok()) call occ%get_text('INTITULE', text, st)
        if (st%failed()) return
        act%label = text(1:min(16, len(text)))            ! Code_Aster's K16
        act%operation = list(1)%s
        act%extraction = any(names_equal(list, 'EXTRACTION'))
        act%mean = any(names_equal(list, 'MOYENNE'))
        if (size(list) == 2 .and. .not. (act%extraction .and. act%mean)) then
            call occ%error_at('OPERATION', 'two operations are EXTRACTION and MOYENNE ' // &
                'together', st)
            return
        end if
        act%frame = 'GLOBAL'
        if (occ%has('REPERE')) call occ%get_text('REPERE', act%frame, st)
        if (st%failed()) return
        allocate (act%asked(0))
        if (act%operation == 'EXTREMA' .or. act%operation == 'MOYENNE_ARITH') then
            call refuse_keys('INVARIANT ELEM_PRINCIPAUX RESULTANTE MOMENT POINT TRAC_NOR ' // &
                'TRAC_DIR DIRECTION VECT_Y ANGL_NAUT ORIGINE AXE_Z')
            if (st%ok() .and. act%frame /= 'GLOBAL') call occ%error_at('REPERE', &
                'OPERATION=''' // act%operation // ''' reads the components as they are ' // &
                '(REPERE=''GLOBAL'')', st)
            if (st%ok() .and. occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', act%asked, st)
            act%all_components = .not. occ%has('NOM_CMP')
            return
        end if
        if (.not. (occ%has('GROUP_NO') .or. occ%has('NOEUD'))) then
            call occ%error_at('OPERATION', 'give the nodes: GROUP_NO or NOEUD', st)
            return
        end if
        n = count([occ%has('TOUT_CMP'), occ%has('NOM_CMP'), occ%has('INVARIANT'), &
                   occ%has('ELEM_PRINCIPAUX'), occ%has('RESULTANTE')])
        if (n /= 1) then
            call occ%error_at('OPERATION', 'give one of TOUT_CMP, NOM_CMP, INVARIANT, ' // &
                'ELEM_PRINCIPAUX, RESULTANTE (the quantity to read)', st)
            return
        end if
        if (occ%has('VECT_Y')) then
            call occ%error_at('VECT_Y', 'three-dimensional local frames (VECT_Y) are not ' // &
                'built by parasol: REPERE GLOBAL, LOCAL, POLAIRE, UTILISATEUR, ' // &
                'CYLINDRIQUE are', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', act%asked, st)
        act%all_components = occ%has('TOUT_CMP')
        if (occ%has('INVARIANT')) then
            act%quantity = Q_INVARIANTS
        else if (occ%has('ELEM_PRINCIPAUX')) then
            act%quantity = Q_PRINCIPAL
        else if (occ%has('TRAC_NOR')) then
            act%quantity = Q_TRAC_NOR
        else if (occ%has('TRAC_DIR')) then
            act%quantity = Q_TRAC_DIR
            call read_point(occ, 'DIRECTION', 'the direction of the traction', act%direction, st)
            if (st%failed()) return
        else if (occ%has('RESULTANTE')) then
            act%quantity = Q_SUM
            if (.not. act%extraction .or. act%mean) then
                call occ%error_at('RESULTANTE', 'RESULTANTE is computed by ' // &
                    'OPERATION=''EXTRACTION'' alone', st)
                return
            end if
            call occ%get_texts('RESULTANTE', names, st)
            if (st%failed()) return
            act%n_resultant = size(names)
            act%asked = names
            if (occ%has('MOMENT')) then
                call occ%get_texts('MOMENT', more, st)
                if (st%failed()) return
                act%n_moment = size(more)
                act%asked = [names, more]
                if (act%n_resultant /= 3 .or. act%n_moment /= 3) then
                    call occ%error_at('MOMENT', 'a moment is computed from three ' // &
                        'RESULTANTE and three MOMENT components (DX DY DZ, DRX DRY DRZ): ' // &
                        'Code_Aster reads shorter lists beyond their end', st, &
                        STATUS_NOT_IMPLEMENTED)
                    return
                end if
                call read_point(occ, 'POINT', 'the point of the moments', act%point, st)
            end if
        end if
        if (st%failed()) return
        if (act%frame == 'UTILISATEUR') then
            if (.not. occ%has('ANGL_NAUT')) then
                call occ%error_at('REPERE', 'REPERE=''UTILISATEUR'' needs ANGL_NAUT, the ' // &
                    'frame''s nautical angles in degrees', st)
                return
            end if
            call occ%get_reals('ANGL_NAUT', values, st)
            if (st%ok()) act%angles = values(1:3)
        else if (act%frame == 'CYLINDRIQUE') then
            if (.not. occ%has('ORIGINE')) then
                call occ%error_at('REPERE', 'REPERE=''CYLINDRIQUE'' needs ORIGINE and ' // &
                    'AXE_Z, a point of the axis and its direction', st)
                return
            end if
            call occ%get_reals('ORIGINE', values, st)
            if (st%ok()) act%origin = values(1:3)
            if (st%ok()) call occ%get_reals('AXE_Z', values, st)
            if (st%failed()) return
            if (sum(values(1:3)**2) < 1.0e-6_dp) then
                call occ%error_at('AXE_Z', 'AXE_Z has no direction (its length is 0)', st)
                return
            end if
            act%axis = values(1:3) * (1.0_dp / sqrt(sum(values(1:3)**2)))
        end if
        if (st%failed()) return
        if (occ%has('MOYE_NOEUD')) then
            call occ%get_text('MOYE_NOEUD', text, st)
            act%average = text == 'OUI'
        end if
    contains
        subroutine refuse_keys(keys)
            character(len=*), intent(in) :: keys
            type(string_t), allocatable :: words(:)
            integer :: w
            words = split_names(keys)
            do w = 1, size(words)
                if (st%ok() .and. occ%has(words(w)%s)) call occ%error_at(words(w)%s, &
                    'OPERATION=''' // act%operation // ''' does not take ' // words(w)%s, st)
            end do
        end subroutine refuse_keys
    end subroutine read_action

    !> A point or direction of 2 or 3 components at `key` (the third 0 when two are given).
    subroutine read_point(occ, key, what, v, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, what
        real(dp), intent(inout) :: v(3)
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: values(:)
        call occ%get_reals(key, values, st)
        if (st%failed()) return
        if (size(values) < 2 .or. size(values) > 3) then
            call occ%error_at(key, key // ' is ' // what // ': 2 or 3 components', st)
            return
        end if
        v = 0.0_dp
        v(1:size(values)) = values
    end subroutine read_point

    ! ---- EXTRACTION, MOYENNE, RESULTANTE along the nodes -------------------------------

    !> The rows of one field for an EXTRACTION / MOYENNE / RESULTANTE occurrence.
    subroutine path_rows(ctx, occ, act, src, mesh, t, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: raw(:), out(:)
        integer, allocatable :: nodes(:), cells(:)
        type(path_values_t) :: pv
        real(dp), allocatable :: frame1(:, :), frame2(:, :), absc(:)
        integer :: kind
        logical :: planar
        if (src%f%location /= FIELD_NOEU .and. src%f%location /= FIELD_ELNO) then
            call occ%error_at(field_key(src), 'POST_RELEVE_T reads nodal (NOEU) and ' // &
                'element-node (ELNO) fields; ' // field_label(src) // ' is ' // &
                field_location_name(src%f) // ' (compute its _ELNO or _NOEU form with ' // &
                'CALC_CHAMP)', st)
            return
        end if
        kind = value_kind(src%f%quantity)
        call components_to_read(occ, act, src, kind, raw, out, st)
        if (st%failed()) return
        call listed_nodes(occ, mesh, nodes, st)
        if (st%failed()) return
        if (src%f%location == FIELD_NOEU) then
            call keep_holding_nodes(occ, act, src, nodes, st)
        else
            call cells_around(occ, act, src, mesh, nodes, cells, st)
        end if
        if (st%failed()) return
        call read_values(occ, act, src, mesh, kind, nodes, cells, raw, pv, st)
        if (st%failed()) return
        planar = .true.
        if (act%frame == 'LOCAL' .or. act%frame == 'POLAIRE' .or. &
            act%quantity == Q_TRAC_NOR) then
            call plane_frames(ctx, occ, act, src, mesh, nodes, frame1, frame2, planar, st)
            if (st%failed() .or. .not. planar) return
        end if
        call compute_quantities(occ, act, src, kind, raw, out, nodes, frame1, frame2, pv, st)
        if (st%failed()) return
        absc = path_abscissae(mesh%coords(:, nodes))
        if (act%quantity == Q_SUM) then
            call sum_rows(occ, act, src, mesh, nodes, pv, t, st)
        else
            if (act%extraction) call extraction_rows(act, src, mesh, nodes, absc, pv, t, st)
            if (st%ok() .and. act%mean) call mean_rows(ctx, occ, act, src, nodes, absc, pv, &
                                                        t, st)
        end if
    end subroutine path_rows


    !> The components read at each point (`raw`) and the quantities written (`out`).
    subroutine components_to_read(occ, act, src, kind, raw, out, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        integer, intent(in) :: kind
        type(string_t), allocatable, intent(out) :: raw(:), out(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: asked(:), kept(:)
        integer :: k, j, slots
        allocate (raw(0), out(0))
        if (act%all_components) then
            asked = held_components(src%f)
        else
            asked = act%asked
        end if
        do k = 1, size(asked)
            if (field_component(src%f, asked(k)%s) == 0) then
                call occ%error_at(trim(merge('NOM_CMP   ', 'RESULTANTE', act%quantity /= Q_SUM)), &
                    'component ' // asked(k)%s // ' is not one of ' // field_label(src) // &
                    ' (it has ' // names_text(src%f%components) // ')', st)
                return
            end if
        end do
        slots = tensor_row(src%f)
        select case (act%quantity)
        case (Q_COMPONENTS)
            if (act%frame == 'LOCAL' .or. act%frame == 'POLAIRE') then
                ! Code_Aster keeps the components a plane frame turns, in the quantity's
                ! order (rvcpnc)
                allocate (kept(0))
                if (kind == KIND_VECTOR) then
                    do j = 1, 6
                        if (any(names_equal(asked, VECTOR_CMPS(j)))) kept = [kept, &
                            string_t(trim(VECTOR_CMPS(j)))]
                    end do
                else if (kind == KIND_TENSOR .and. slots >= 1 .and. slots <= 2) then
                    do j = 1, 6
                        if (any(names_equal(asked, TENSOR_SLOT_NAMES(j, slots)))) kept = &
                            [kept, string_t(trim(TENSOR_SLOT_NAMES(j, slots)))]
                    end do
                end if
                if (size(kept) == 0) then
                    call occ%error_at('REPERE', 'REPERE=''' // act%frame // ''' turns ' // &
                        'displacements (DX .. DRZ) and stress or strain tensors (SIXX .. ' // &
                        'SIYZ, EPXX .. EPYZ); none is asked of ' // field_label(src), st, &
                        STATUS_NOT_IMPLEMENTED)
                    return
                end if
                out = kept
                if (kind == KIND_VECTOR) then
                    raw = vector_names()
                else
                    raw = tensor_names(slots)
                end if
            else
                raw = asked
                out = asked
            end if
        case (Q_INVARIANTS, Q_PRINCIPAL)
            if (kind /= KIND_TENSOR .or. slots < 1 .or. slots > 2) then
                call occ%error_at(trim(merge('INVARIANT      ', 'ELEM_PRINCIPAUX', &
                    act%quantity == Q_INVARIANTS)), 'the invariants and principal values ' // &
                    'are those of a stress or strain tensor (SIXX .. SIYZ, EPXX .. EPYZ); ' // &
                    field_label(src) // ' holds none', st)
                return
            end if
            raw = tensor_names(slots)
            if (act%quantity == Q_INVARIANTS) then
                out = split_names('VMIS TRESCA TRACE DETER')
            else
                out = split_names('PRIN_1 PRIN_2 PRIN_3 VECT_1_X VECT_1_Y VECT_1_Z ' // &
                    'VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y VECT_3_Z')
            end if
        case (Q_TRAC_DIR, Q_TRAC_NOR)
            if (kind == KIND_VECTOR) then
                raw = vector_names()
                out = split_names(merge('TRAC_DIR', 'TRAC_NOR', act%quantity == Q_TRAC_DIR))
            else if (kind == KIND_TENSOR .and. slots >= 1 .and. slots <= 2) then
                raw = tensor_names(slots)
                if (act%quantity == Q_TRAC_DIR) then
                    out = split_names('TR_DIR_1 TR_DIR_2 TR_DIR_3')
                else
                    out = split_names('TR_NOR_1 TR_NOR_2 TR_NOR_3')
                end if
            else
                call occ%error_at(merge('TRAC_DIR', 'TRAC_NOR', act%quantity == Q_TRAC_DIR), &
                    'a traction is that of a displacement-like vector or of a stress ' // &
                    'tensor; ' // field_label(src) // ' is neither', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
        case (Q_SUM)
            raw = asked
            if (act%n_moment > 0) then
                out = split_names('RESULT_X RESULT_Y RESULT_Z MOMENT_X MOMENT_Y MOMENT_Z')
            else
                out = asked
            end if
        end select
        if (st%failed()) return
        if ((act%frame == 'UTILISATEUR' .or. act%frame == 'CYLINDRIQUE') .and. &
            .not. (kind == KIND_VECTOR .and. src%f%location == FIELD_NOEU) .and. &
            .not. (kind == KIND_TENSOR .and. src%f%location == FIELD_ELNO)) then
            call occ%error_at('REPERE', 'REPERE=''' // act%frame // ''' turns the ' // &
                'displacements of a nodal DEPL_R field and the tensors of an ELNO stress ' // &
                'or strain field (Code_Aster''s rvchn1, rvche1); ' // field_label(src) // &
                ' is ' // field_location_name(src%f) // ' ' // src%f%quantity, st)
        end if
    end subroutine components_to_read

    function vector_names() result(names)
        type(string_t), allocatable :: names(:)
        integer :: j
        allocate (names(6))
        do j = 1, 6
            names(j)%s = trim(VECTOR_CMPS(j))
        end do
    end function vector_names

    function tensor_names(row) result(names)
        integer, intent(in) :: row
        type(string_t), allocatable :: names(:)
        integer :: j
        allocate (names(6))
        do j = 1, 6
            names(j)%s = trim(TENSOR_SLOT_NAMES(j, row))
        end do
    end function tensor_names


    function split_names(text) result(names)
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: names(:)
        call split_words(text, names)
    end function split_names

    pure function names_equal(names, name) result(hit)
        type(string_t), intent(in) :: names(:)
        character(len=*), intent(in) :: name
        logical :: hit(size(names))
        integer :: k
        do k = 1, size(names)
            hit(k) = names(k)%s == trim(name)
        end do
    end function names_equal

    function names_text(names) result(text)
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(names)
            if (k > 1) text = text // ' '
            text = text // names(k)%s
        end do
    end function names_text

    ! ---- the nodes and cells ---------------------------------------------------------------

    !> NOEUD then the nodes of each GROUP_NO in the group's order, each node once (rvgnoe).
    subroutine listed_nodes(occ, mesh, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: nodes(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        integer, allocatable :: all(:)
        logical, allocatable :: seen(:)
        integer(i4) :: g
        integer :: k, n
        allocate (all(0), nodes(0))
        if (occ%has('NOEUD')) then
            call occ%get_texts('NOEUD', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                all = [all, int(find_node(mesh, names(k)%s, st))]
                if (st%failed()) then
                    call relocate_at(occ, 'NOEUD', st)
                    return
                end if
            end do
        end if
        if (occ%has('GROUP_NO')) then
            call occ%get_texts('GROUP_NO', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                g = find_node_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_NO', st)
                    return
                end if
                all = [all, int(nodes_of_group(mesh, g))]
            end do
        end if
        allocate (seen(mesh%n_nodes), source=.false.)
        deallocate (nodes)
        allocate (nodes(size(all)))
        n = 0
        do k = 1, size(all)
            if (seen(all(k))) cycle
            seen(all(k)) = .true.
            n = n + 1
            nodes(n) = all(k)
        end do
        nodes = nodes(1:n)
        if (n == 0) call occ%error_at(trim(merge('GROUP_NO', 'NOEUD   ', occ%has('GROUP_NO'))), &
            'the node list is empty', st)
    end subroutine listed_nodes

    !> A nodal field: the nodes holding a component NOM_CMP / TOUT_CMP asks for (rvouex).
    subroutine keep_holding_nodes(occ, act, src, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        integer, allocatable, intent(inout) :: nodes(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: keep(:)
        integer, allocatable :: ks(:)
        integer :: i, j
        if (.not. (act%all_components .or. occ%has('NOM_CMP'))) return
        if (act%all_components) then
            ks = [(j, j=1, size(src%f%components))]
        else
            allocate (ks(size(act%asked)))
            do j = 1, size(act%asked)
                ks(j) = field_component(src%f, act%asked(j)%s)
            end do
            ks = pack(ks, ks > 0)
        end if
        allocate (keep(size(nodes)))
        do i = 1, size(nodes)
            keep(i) = any(src%f%node_has(ks, nodes(i)))
        end do
        nodes = pack(nodes, keep)
        if (size(nodes) == 0) call occ%error_at(trim(merge('GROUP_NO', 'NOEUD   ', &
            occ%has('GROUP_NO'))), 'no listed node holds a component asked of ' // &
            field_label(src), st, STATUS_MODEL_ERROR)
    end subroutine keep_holding_nodes

    !> An ELNO field: the cells around the listed nodes that hold a component asked for,
    !> without sub-points, within GROUP_MA / MAILLE when given, in increasing number (rvouex);
    !> every listed node must belong to one.
    subroutine cells_around(occ, act, src, mesh, nodes, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: nodes(:)
        integer, allocatable, intent(out) :: cells(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: listed(:), chosen(:), allowed(:), covered(:)
        integer, allocatable :: ks(:)
        integer(i4) :: c
        integer :: k, j, i
        logical :: layered
        allocate (listed(mesh%n_nodes), source=.false.)
        listed(nodes) = .true.
        if (occ%has('GROUP_MA') .or. occ%has('MAILLE')) then
            call selected_cells(occ, mesh, allowed, st)
            if (st%failed()) return
        else
            allocate (allowed(mesh%n_cells), source=.true.)
        end if
        allocate (ks(0))
        if (act%all_components) then
            ks = [(j, j=1, size(src%f%components))]
        else if (occ%has('NOM_CMP')) then
            do j = 1, size(act%asked)
                ks = [ks, int(field_component(src%f, act%asked(j)%s))]
            end do
        end if
        allocate (chosen(mesh%n_cells), source=.false.)
        layered = .false.
        do c = 1, min(mesh%n_cells, src%f%n_cells)
            if (.not. allowed(c) .or. src%f%n_points(c) == 0) cycle
            if (.not. any(listed(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)))) &
                cycle
            if (size(ks) > 0) then
                if (.not. any([(any(src%f%sets(src%f%cell_set(c))%cmp == ks(j)), &
                                j=1, size(ks))])) cycle
            end if
            if (src%f%n_subpoints(c) > 1) then
                layered = .true.                ! Code_Aster leaves them out (PREPOST_36)
                cycle
            end if
            chosen(c) = .true.
        end do
        cells = pack([(k, k=1, mesh%n_cells)], chosen)
        if (size(cells) == 0) then
            if (layered) then
                call occ%error_at(field_key(src), field_label(src) // ' has sub-points ' // &
                    '(plate layers) on the cells around the nodes, and POST_RELEVE_T leaves ' // &
                    'such cells out, as Code_Aster does: extract a layer first ' // &
                    '(POST_CHAMP EXTR_COQUE)', st, STATUS_MODEL_ERROR)
            else
                call occ%error_at(field_key(src), 'no cell around the listed nodes holds ' // &
                    field_label(src), st, STATUS_MODEL_ERROR)
            end if
            return
        end if
        allocate (covered(mesh%n_nodes), source=.false.)
        do k = 1, size(cells)
            c = int(cells(k), i4)
            covered(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)) = .true.
        end do
        do i = 1, size(nodes)
            if (.not. covered(nodes(i))) then
                call occ%error_at(trim(merge('GROUP_NO', 'NOEUD   ', occ%has('GROUP_NO'))), &
                    'node ' // node_name(mesh, int(nodes(i), i4)) // ' is on no cell ' // &
                    'holding ' // field_label(src) // ' (within GROUP_MA / MAILLE when given)', &
                    st, STATUS_MODEL_ERROR)
                return
            end if
        end do
    end subroutine cells_around

    ! ---- the values at the points ----------------------------------------------------------

    !> The `raw` components at each point: a node's value (a nodal field; an ELNO field
    !> averaged over the chosen cells holding the node), or a node's value in each of its
    !> cells (MOYE_NOEUD='NON'); turned first by UTILISATEUR / CYLINDRIQUE. A component a
    !> point lacks is 0.
    subroutine read_values(occ, act, src, mesh, kind, nodes, cells, raw, pv, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: kind
        integer, intent(in) :: nodes(:)
        integer, allocatable, intent(in) :: cells(:)
        type(string_t), intent(in) :: raw(:)
        type(path_values_t), intent(out) :: pv
        type(status_t), intent(inout) :: st
        integer, allocatable :: ks(:), around_ptr(:), around(:)
        real(dp) :: pgl(3, 3), value(size(raw)), total(size(raw))
        integer :: i, j, n, c, m, nbm, np
        logical :: ok
        allocate (ks(size(raw)))
        do j = 1, size(raw)
            ks(j) = field_component(src%f, raw(j)%s)
        end do
        pv%names = raw
        if (act%frame == 'UTILISATEUR') call user_frame(act%angles, pgl)
        if (src%f%location == FIELD_NOEU) then
            allocate (pv%node(size(nodes)), pv%cell(size(nodes)), pv%v(size(raw), size(nodes)))
            pv%node = nodes
            pv%cell = 0
            do i = 1, size(nodes)
                n = nodes(i)
                do j = 1, size(raw)
                    value(j) = 0.0_dp
                    if (ks(j) > 0) then
                        if (src%f%node_has(ks(j), n)) value(j) = src%f%node_values(ks(j), n)
                    end if
                end do
                if (act%frame == 'UTILISATEUR' .or. act%frame == 'CYLINDRIQUE') then
                    call node_frame(n, ok)
                    if (.not. ok) return
                    call turn_vectors(src%f, n, pgl, raw, value)
                end if
                pv%v(:, i) = value
            end do
            call check_values(pv)
            return
        end if
        ! ELNO: the chosen cells around each listed node, in increasing number
        call cells_of_nodes(mesh, nodes, cells, around_ptr, around)
        np = size(nodes)
        if (.not. act%average) np = around_ptr(size(nodes) + 1) - 1
        allocate (pv%node(np), pv%cell(np), pv%v(size(raw), np))
        m = 0
        do i = 1, size(nodes)
            n = nodes(i)
            nbm = around_ptr(i + 1) - around_ptr(i)
            total = 0.0_dp
            do c = around_ptr(i), around_ptr(i + 1) - 1
                call cell_node_value(around(c), n, value)
                if (st%failed()) return
                if (act%average) then
                    total = total + value
                else
                    m = m + 1
                    pv%node(m) = n
                    pv%cell(m) = around(c)
                    pv%v(:, m) = value
                end if
            end do
            if (act%average) then
                if (nbm > 1) total = total / nbm
                pv%node(i) = n
                pv%cell(i) = 0
                pv%v(:, i) = total
            end if
        end do
        call check_values(pv)
    contains
        !> The frame at node n (CYLINDRIQUE); false and an error on the axis.
        subroutine node_frame(node, ok)
            integer, intent(in) :: node
            logical, intent(out) :: ok
            ok = .true.
            if (act%frame /= 'CYLINDRIQUE') return
            call cylindrical_frame(mesh%coords(:, node), act%origin, act%axis, pgl, ok)
            if (.not. ok) call occ%error_at('ORIGINE', 'node ' // node_name(mesh, &
                int(node, i4)) // ' is on the axis of REPERE=''CYLINDRIQUE'': it has no ' // &
                'radial direction', st, STATUS_MODEL_ERROR)
        end subroutine node_frame

        !> The raw components of cell `cell` at node `node` (its ELNO point), turned.
        subroutine cell_node_value(cell, node, v)
            integer, intent(in) :: cell, node
            real(dp), intent(out) :: v(:)
            integer :: p, jj
            integer(i8) :: pos
            logical :: frame_ok
            real(dp) :: s(6), r(6)
            integer :: slot(size(raw))
            p = findloc(mesh%cell_nodes(mesh%cell_ptr(cell):mesh%cell_ptr(cell + 1) - 1), &
                        node, dim=1)
            do jj = 1, size(raw)
                v(jj) = 0.0_dp
                if (ks(jj) == 0) cycle
                pos = field_position(src%f, int(cell, i4), int(p, i4), 1_i4, int(ks(jj), i4))
                if (pos > 0) v(jj) = src%f%values(pos)
            end do
            if (act%frame /= 'UTILISATEUR' .and. act%frame /= 'CYLINDRIQUE') return
            if (kind /= KIND_TENSOR) return
            call node_frame(node, frame_ok)
            if (.not. frame_ok) return
            ! the tensor slots of the cell's components (rvche1's mapping)
            s = 0.0_dp
            slot = 0
            do jj = 1, size(raw)
                slot(jj) = tensor_slot(raw(jj)%s)
            end do
            call cell_tensor(cell, p, s)
            r = rotate_tensor(pgl, s)
            do jj = 1, size(raw)
                if (slot(jj) > 0 .and. ks(jj) > 0) then
                    pos = field_position(src%f, int(cell, i4), int(p, i4), 1_i4, &
                                         int(ks(jj), i4))
                    if (pos > 0) v(jj) = r(slot(jj))
                end if
            end do
        end subroutine cell_node_value

        !> The tensor of the cell at point p from its components (absent ones 0).
        subroutine cell_tensor(cell, p, s)
            integer, intent(in) :: cell, p
            real(dp), intent(out) :: s(6)
            integer :: kk, sl
            integer(i8) :: pos
            s = 0.0_dp
            do kk = 1, size(src%f%components)
                sl = tensor_slot(src%f%components(kk)%s)
                if (sl == 0) cycle
                pos = field_position(src%f, int(cell, i4), int(p, i4), 1_i4, int(kk, i4))
                if (pos > 0) s(sl) = src%f%values(pos)
            end do
        end subroutine cell_tensor

        subroutine check_values(values)
            type(path_values_t), intent(in) :: values
            integer :: a, b
            do b = 1, size(values%v, 2)
                do a = 1, size(values%v, 1)
                    if (abs(values%v(a, b)) > VALUE_LIMIT) then
                        call occ%error_at(field_key(src), 'component ' // &
                            values%names(a)%s // ' of ' // field_label(src) // ' at node ' // &
                            node_name(mesh, int(values%node(b), i4)) // ' is ' // &
                            real_e13(values%v(a, b)) // ', beyond what POST_RELEVE_T sums ' // &
                            'and turns (1E+200)', st, STATUS_MODEL_ERROR)
                        return
                    end if
                end do
            end do
        end subroutine check_values
    end subroutine read_values

    !> The position (1..6) of a component in DX DY DZ DRX DRY DRZ, 0 for none.
    pure integer function vector_index(name) result(j)
        character(len=*), intent(in) :: name
        do j = 1, 6
            if (trim(VECTOR_CMPS(j)) == name) return
        end do
        j = 0
    end function vector_index

    !> The tensor slot (1..6: xx yy zz xy xz yz) of a component name, 0 for none.
    pure integer function tensor_slot(name) result(slot)
        character(len=*), intent(in) :: name
        integer :: row
        do row = 1, size(TENSOR_SLOT_NAMES, 2)
            do slot = 1, 6
                if (trim(TENSOR_SLOT_NAMES(slot, row)) == name) return
            end do
        end do
        slot = 0
    end function tensor_slot

    !> Turns (DX, DY, DZ) and (DRX, DRY, DRZ) of node n by pgl, writing back the components
    !> the node holds (rvchn1, rvchn2).
    subroutine turn_vectors(f, n, pgl, raw, value)
        type(field_t), intent(in) :: f
        integer, intent(in) :: n
        real(dp), intent(in) :: pgl(3, 3)
        type(string_t), intent(in) :: raw(:)
        real(dp), intent(inout) :: value(:)
        real(dp) :: v(3), w(3)
        integer :: group, j, k, kk
        logical :: held(3)
        do group = 0, 1
            v = 0.0_dp
            held = .false.
            do j = 1, 3
                kk = field_component(f, trim(VECTOR_CMPS(3 * group + j)))
                if (kk == 0) cycle
                if (.not. f%node_has(kk, n)) cycle
                held(j) = .true.
                v(j) = f%node_values(kk, n)
            end do
            if (.not. any(held)) cycle
            w = rotate_vector(pgl, v)
            do k = 1, size(raw)
                do j = 1, 3
                    if (held(j) .and. raw(k)%s == trim(VECTOR_CMPS(3 * group + j))) value(k) = w(j)
                end do
            end do
        end do
    end subroutine turn_vectors

    !> For each listed node, the chosen cells holding it, in increasing cell number (CSR).
    subroutine cells_of_nodes(mesh, nodes, cells, ptr, around)
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: nodes(:), cells(:)
        integer, allocatable, intent(out) :: ptr(:), around(:)
        integer, allocatable :: position(:), fill(:)
        integer :: k, i, c, a
        allocate (position(mesh%n_nodes), source=0)
        do i = 1, size(nodes)
            position(nodes(i)) = i
        end do
        allocate (ptr(size(nodes) + 1), source=0)
        do k = 1, size(cells)
            c = cells(k)
            do a = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                i = position(mesh%cell_nodes(a))
                if (i > 0) ptr(i + 1) = ptr(i + 1) + 1
            end do
        end do
        ptr(1) = 1
        do i = 1, size(nodes)
            ptr(i + 1) = ptr(i + 1) + ptr(i)
        end do
        allocate (around(ptr(size(nodes) + 1) - 1), fill(size(nodes)))
        fill = ptr(1:size(nodes))
        do k = 1, size(cells)                       ! cells ascending: each list ascends
            c = cells(k)
            do a = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                i = position(mesh%cell_nodes(a))
                if (i == 0) cycle
                around(fill(i)) = c
                fill(i) = fill(i) + 1
            end do
        end do
    end subroutine cells_of_nodes

    ! ---- plane frames and the quantities ---------------------------------------------------

    !> The frames of REPERE LOCAL / POLAIRE and TRAC_NOR at the listed nodes: `first` the
    !> tangent (LOCAL) or radial (POLAIRE) direction, `second` the normal z x t (LOCAL) or
    !> minus the orthoradial one (POLAIRE, as rvcalq turns it). The nodes must lie in one
    !> plane z = constant (rvchgr; POLAIRE: the whole mesh): otherwise a warning and no
    !> rows for this field (`planar` false), as Code_Aster does.
    subroutine plane_frames(ctx, occ, act, src, mesh, nodes, first, second, planar, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: nodes(:)
        real(dp), allocatable, intent(out) :: first(:, :), second(:, :)
        logical, intent(out) :: planar
        type(status_t), intent(inout) :: st
        real(dp) :: zref, r(2), n(2)
        logical :: ok
        integer :: i
        allocate (first(2, size(nodes)), second(2, size(nodes)))
        planar = .true.
        if (act%frame == 'POLAIRE' .or. act%quantity == Q_TRAC_NOR) then
            zref = mesh%coords(3, 1)
            do i = 1, mesh%n_nodes
                if (.not. same_z(zref, mesh%coords(3, i))) then
                    if (act%quantity == Q_TRAC_NOR) then
                        call occ%error_at('TRAC_NOR', 'TRAC_NOR takes the normal of the ' // &
                            'node path in the plane: the mesh must lie in one plane z = ' // &
                            'constant', st)
                        return
                    end if
                    planar = .false.
                    exit
                end if
            end do
        end if
        zref = mesh%coords(3, nodes(1))
        do i = 1, size(nodes)
            if (.not. same_z(zref, mesh%coords(3, nodes(i)))) planar = .false.
        end do
        if (.not. planar) then
            call warn_at(ctx, occ, 'REPERE', 'the frame ' // act%frame // ' is that of ' // &
                'nodes in one plane z = constant; they are not: no row for ' // &
                field_label(src) // ' (Code_Aster''s alarm POSTRELE_28)')
            return
        end if
        if (act%frame == 'POLAIRE' .and. act%quantity /= Q_TRAC_NOR) then
            do i = 1, size(nodes)
                call polar_frame(mesh%coords(1, nodes(i)), mesh%coords(2, nodes(i)), r, n)
                first(:, i) = r
                second(:, i) = -n
            end do
        else
            call plane_local_frames(mesh%coords(:, nodes), first, second, ok)
            if (.not. ok) call occ%error_at('REPERE', 'two consecutive listed nodes are at ' // &
                'the same place: the node path has no tangent there', st, STATUS_MODEL_ERROR)
        end if
    contains
        !> rvegal(1e-3, 'R'): |a - b| < 1e-3 |a| (1e-3 when |a| < 1e-3).
        pure logical function same_z(a, b)
            real(dp), intent(in) :: a, b
            real(dp) :: threshold
            threshold = 1.0e-3_dp
            if (abs(a) >= 1.0e-3_dp) threshold = threshold * abs(a)
            same_z = abs(a - b) < threshold
        end function same_z
    end subroutine plane_frames

    !> The quantities `out` from the `raw` components at each point (rvcalq), in place.
    subroutine compute_quantities(occ, act, src, kind, raw, out, nodes, first, second, pv, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        integer, intent(in) :: kind
        type(string_t), intent(in) :: raw(:), out(:)
        integer, intent(in) :: nodes(:)
        real(dp), allocatable, intent(in) :: first(:, :), second(:, :)
        type(path_values_t), intent(inout) :: pv
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: q(:, :)
        integer, allocatable :: along(:)
        real(dp) :: v(size(raw)), a(2), b(2), d(3), vp(3), vecs(3, 3)
        integer :: m, j, k, i
        logical :: turned
        turned = act%quantity == Q_COMPONENTS .and. (act%frame == 'LOCAL' .or. &
                 act%frame == 'POLAIRE')
        if (act%quantity == Q_SUM .or. (act%quantity == Q_COMPONENTS .and. .not. turned)) &
            return
        allocate (q(size(out), size(pv%node)), source=0.0_dp)
        allocate (along(maxval(nodes)), source=0)
        do i = 1, size(nodes)
            along(nodes(i)) = i
        end do
        d = act%direction
        where (abs(d) < 1.0e-6_dp) d = 0.0_dp
        do m = 1, size(pv%node)
            v = pv%v(:, m)
            i = along(pv%node(m))
            if (allocated(first)) then
                a = first(:, i)
                b = second(:, i)
            end if
            select case (act%quantity)
            case (Q_COMPONENTS)
                do k = 1, size(out)
                    if (kind == KIND_VECTOR) then
                        j = vector_index(out(k)%s)
                    else
                        j = tensor_slot(out(k)%s)
                    end if
                    q(k, m) = turned_value(kind, j, v, a, b)
                end do
            case (Q_INVARIANTS)
                if (any(abs(v) > CUBE_LIMIT)) then
                    call occ%error_at('INVARIANT', 'the tensor of ' // field_label(src) // &
                        ' reaches ' // real_e13(maxval(abs(v))) // ': its determinant ' // &
                        '(DETER) is beyond double precision (the components stay below ' // &
                        '1E+100)', st, STATUS_MODEL_ERROR)
                    return
                end if
                call tensor_invariants(v, q(1, m), q(2, m), q(3, m), q(4, m))
            case (Q_PRINCIPAL)
                call principal_stresses(v, vp, vecs)
                q(1:3, m) = vp
                q(4:6, m) = vecs(:, 1)
                q(7:9, m) = vecs(:, 2)
                q(10:12, m) = vecs(:, 3)
            case (Q_TRAC_DIR)
                call traction(kind, v, d, q(:, m))
            case (Q_TRAC_NOR)
                call traction(kind, v, [b(1), b(2), 0.0_dp], q(:, m))
            end select
        end do
        pv%names = out
        call move_alloc(q, pv%v)
    end subroutine compute_quantities



    ! ---- the rows ---------------------------------------------------------------------------

    !> A new row with INTITULE and what names the field (RESU, NOM_CHAM, NUME_ORDRE, INST;
    !> or CHAM_GD).
    subroutine start_row(t, act, src, r, st)
        type(table_t), intent(inout) :: t
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        integer, intent(out) :: r
        type(status_t), intent(inout) :: st
        call table_add_rows(t, 1)
        r = t%n_rows
        call put_text(t, 'INTITULE', r, act%label, 16, st)
        if (src%from_result) then
            call put_text(t, 'RESU', r, src%resu, 8, st)
            call put_text(t, 'NOM_CHAM', r, src%nom_cham, 16, st)
            call put_int(t, 'NUME_ORDRE', r, src%nume_ordre, st)
            call put_real(t, 'INST', r, src%inst, st)
        else
            call put_text(t, 'CHAM_GD', r, src%cham_gd, 8, st)
        end if
    end subroutine start_row

    !> The column `name` (added after the others when the table lacks it, as Code_Aster's
    !> tbajpa adds it).
    integer function column_of(t, name, kind, width, st) result(c)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        integer, intent(in) :: kind, width
        type(status_t), intent(inout) :: st
        c = table_find_column(t, name)
        if (c > 0) return
        if (kind == TABLE_TEXT) then
            call table_add_column(t, name, kind, c, st, width)
        else
            call table_add_column(t, name, kind, c, st)
        end if
    end function column_of

    !> A text cell; a text longer than the column's K width widens it (parasol's names may
    !> be longer than Code_Aster's eight characters).
    subroutine put_text(t, name, r, text, width, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name, text
        integer, intent(in) :: r, width
        type(status_t), intent(inout) :: st
        integer :: c
        if (st%failed()) return
        c = column_of(t, name, TABLE_TEXT, width, st)
        if (st%failed()) return
        if (len_trim(text) > t%columns(c)%width) t%columns(c)%width = &
            table_text_width_for(len_trim(text))
        call table_set_text(t, c, r, text, st)
    end subroutine put_text

    subroutine put_real(t, name, r, value, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        integer, intent(in) :: r
        real(dp), intent(in) :: value
        type(status_t), intent(inout) :: st
        integer :: c
        if (st%failed()) return
        c = column_of(t, name, TABLE_REAL, 0, st)
        if (st%ok()) call table_set_real(t, c, r, value, st)
    end subroutine put_real

    subroutine put_int(t, name, r, value, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        integer, intent(in) :: r, value
        type(status_t), intent(inout) :: st
        integer :: c
        if (st%failed()) return
        c = column_of(t, name, TABLE_INT, 0, st)
        if (st%ok()) call table_set_int(t, c, r, int(value, i8), st)
    end subroutine put_int

    !> EXTRACTION: a row per point (rvtecn; MOYE_NOEUD='NON': rvtec0, with MAILLE).
    subroutine extraction_rows(act, src, mesh, nodes, absc, pv, t, st)
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: nodes(:)
        real(dp), intent(in) :: absc(:)
        type(path_values_t), intent(in) :: pv
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        integer, allocatable :: along(:)
        integer :: m, r, k, n
        allocate (along(maxval(nodes)), source=0)
        do k = 1, size(nodes)
            along(nodes(k)) = k
        end do
        do m = 1, size(pv%node)
            n = pv%node(m)
            call start_row(t, act, src, r, st)
            call put_text(t, 'NOEUD', r, table_entity_label(n), 8, st)
            if (pv%cell(m) > 0) call put_text(t, 'MAILLE', r, &
                table_entity_label(pv%cell(m)), 8, st)
            call put_real(t, 'ABSC_CURV', r, absc(along(n)), st)
            call put_real(t, 'COOR_X', r, mesh%coords(1, n), st)
            call put_real(t, 'COOR_Y', r, mesh%coords(2, n), st)
            call put_real(t, 'COOR_Z', r, mesh%coords(3, n), st)
            do k = 1, size(pv%names)
                call put_real(t, pv%names(k)%s, r, pv%v(k, m), st)
            end do
            if (st%failed()) return
        end do
    end subroutine extraction_rows

    !> The values of each listed node: per-cell values averaged over the node's cells.
    subroutine node_values(nodes, pv, v)
        integer, intent(in) :: nodes(:)
        type(path_values_t), intent(in) :: pv
        real(dp), allocatable, intent(out) :: v(:, :)
        integer, allocatable :: along(:), count(:)
        integer :: m, k
        allocate (v(size(pv%names), size(nodes)), source=0.0_dp)
        allocate (along(maxval(nodes)), source=0, count(size(nodes)))
        count = 0
        do k = 1, size(nodes)
            along(nodes(k)) = k
        end do
        do m = 1, size(pv%node)
            k = along(pv%node(m))
            v(:, k) = v(:, k) + pv%v(:, m)
            count(k) = count(k) + 1
        end do
        do k = 1, size(nodes)
            if (count(k) > 1) v(:, k) = v(:, k) / count(k)
        end do
    end subroutine node_values

    !> MOYENNE: six rows, QUANTITE MOMENT_0 .. MOYE_EXT, of every quantity (rvpstm, rvtamo).
    subroutine mean_rows(ctx, occ, act, src, nodes, absc, pv, t, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        integer, intent(in) :: nodes(:)
        real(dp), intent(in) :: absc(:)
        type(path_values_t), intent(in) :: pv
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        character(len=*), parameter :: NAMES(6) = [character(len=8) :: 'MOMENT_0', &
            'MOMENT_1', 'MINIMUM', 'MAXIMUM', 'MOYE_INT', 'MOYE_EXT']
        real(dp), allocatable :: v(:, :), stats(:, :)
        logical, allocatable :: present(:)
        integer :: k, q, r, missing
        logical :: ok
        call node_values(nodes, pv, v)
        allocate (stats(6, size(pv%names)), present(size(nodes)))
        present = .true.
        do k = 1, size(pv%names)
            call path_statistics(absc, v(k, :), present, stats(:, k), missing, ok)
            if (.not. ok) then
                call occ%error_at('OPERATION', 'MOYENNE is taken along two nodes at ' // &
                    'least; the path of ' // field_label(src) // ' has ' // &
                    to_text(int(size(nodes), i4)), st, STATUS_MODEL_ERROR)
                return
            end if
            if (missing > 0) call warn_at(ctx, occ, 'OPERATION', to_text(int(missing, i4)) // &
                ' segment(s) left out of MOYENNE for a missing value')
        end do
        do q = 1, 6
            call start_row(t, act, src, r, st)
            call put_text(t, 'QUANTITE', r, trim(NAMES(q)), 16, st)
            do k = 1, size(pv%names)
                call put_real(t, pv%names(k)%s, r, stats(q, k), st)
            end do
            if (st%failed()) return
        end do
    end subroutine mean_rows

    !> RESULTANTE: the sums of the components over the nodes; with MOMENT, RESULT_X ..
    !> MOMENT_Z about POINT, the lever arms turned into the user frame (rvpsts, rvtaso).
    subroutine sum_rows(occ, act, src, mesh, nodes, pv, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        integer, intent(in) :: nodes(:)
        type(path_values_t), intent(in) :: pv
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: v(:, :)
        real(dp) :: total(6), arm(3), pgl(3, 3), rx, ry, rz, mx, my, mz
        integer :: j, k, r
        type(string_t), allocatable :: names(:)
        call node_values(nodes, pv, v)
        if (act%n_moment == 0) then
            call start_row(t, act, src, r, st)
            do k = 1, size(pv%names)
                total(1) = 0.0_dp
                do j = 1, size(nodes)
                    total(1) = total(1) + v(k, j)
                end do
                call put_real(t, pv%names(k)%s, r, total(1), st)
            end do
            return
        end if
        if (act%frame /= 'GLOBAL' .and. act%frame /= 'UTILISATEUR') then
            call occ%error_at('REPERE', 'a moment is taken in REPERE GLOBAL or ' // &
                'UTILISATEUR (Code_Aster''s POSTRELE_68)', st)
            return
        end if
        if (act%frame == 'UTILISATEUR') call user_frame(act%angles, pgl)
        total = 0.0_dp
        do j = 1, size(nodes)
            arm = mesh%coords(:, nodes(j)) - act%point
            if (act%frame == 'UTILISATEUR') arm = rotate_vector(pgl, arm)
            rx = v(1, j); ry = v(2, j); rz = v(3, j)
            mx = v(4, j); my = v(5, j); mz = v(6, j)
            mx = arm(2) * rz - arm(3) * ry + mx
            my = arm(3) * rx - arm(1) * rz + my
            mz = arm(1) * ry - arm(2) * rx + mz
            total = total + [rx, ry, rz, mx, my, mz]
        end do
        names = split_names('RESULT_X RESULT_Y RESULT_Z MOMENT_X MOMENT_Y MOMENT_Z')
        call start_row(t, act, src, r, st)
        do k = 1, 6
            call put_real(t, names(k)%s, r, total(k), st)
        end do
    end subroutine sum_rows

    ! ---- EXTREMA, MOYENNE_ARITH ------------------------------------------------------------

    !> The nodes of GROUP_NO, NOEUD, GROUP_MA, MAILLE (their cells' nodes), each once in
    !> increasing number; every node when none is given (reliem).
    subroutine nodes_of_selection(occ, mesh, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: nodes(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: chosen(:)
        integer :: k
        call selected_nodes(occ, mesh, chosen, st)
        if (st%failed()) return
        if (.not. (occ%has('GROUP_NO') .or. occ%has('NOEUD') .or. occ%has('GROUP_MA') .or. &
                   occ%has('MAILLE'))) chosen = .true.
        nodes = pack([(k, k=1, mesh%n_nodes)], chosen)
    end subroutine nodes_of_selection

    !> The components read by EXTREMA / MOYENNE_ARITH: NOM_CMP's that the field has
    !> (others passed over, as prexno passes them over), else all of the field's.
    function extreme_components(act, f) result(ks)
        type(action_t), intent(in) :: act
        type(field_t), intent(in) :: f
        integer, allocatable :: ks(:)
        integer :: j
        if (act%all_components) then
            ks = [(j, j=1, size(f%components))]
        else
            allocate (ks(size(act%asked)))
            do j = 1, size(act%asked)
                ks(j) = field_component(f, act%asked(j)%s)
            end do
            ks = pack(ks, ks > 0)
        end if
    end function extreme_components

    !> EXTREMA of a nodal field: rows MAX, MIN, MAXI_ABS, MINI_ABS with the node (its
    !> number, as Code_Aster's int_to_char8 writes it), the component and the value; the
    !> first node reaching an extreme, components in turn (prexno).
    subroutine extrema_rows(occ, act, src, mesh, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        character(len=*), parameter :: KINDS(4) = [character(len=8) :: 'MAX', 'MIN', &
            'MAXI_ABS', 'MINI_ABS']
        integer, allocatable :: nodes(:), ks(:)
        real(dp) :: best(4), x
        integer :: where(4), which(4), i, j, r, q
        if (src%f%location /= FIELD_NOEU) then
            call occ%error_at(field_key(src), 'EXTREMA of element fields is not built by ' // &
                'parasol: ' // field_label(src) // ' is ' // field_location_name(src%f) // &
                ' (EXTREMA of a nodal field is)', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call nodes_of_selection(occ, mesh, nodes, st)
        if (st%failed()) return
        ks = extreme_components(act, src%f)
        best = [-huge(1.0_dp), huge(1.0_dp), -huge(1.0_dp), huge(1.0_dp)]
        where = 0
        which = 0
        do j = 1, size(ks)
            do i = 1, size(nodes)
                if (.not. src%f%node_has(ks(j), nodes(i))) cycle
                x = src%f%node_values(ks(j), nodes(i))
                if (x > best(1)) call keep(1, x)
                if (abs(x) > best(3)) call keep(3, abs(x))
                if (x < best(2)) call keep(2, x)
                if (abs(x) < best(4)) call keep(4, abs(x))
            end do
        end do
        if (where(1) == 0) then
            call occ%error_at(field_key(src), 'no selected node holds a component of ' // &
                field_label(src) // ': there is no extreme (Code_Aster''s POSTRELE_18)', st, &
                STATUS_MODEL_ERROR)
            return
        end if
        do q = 1, 4
            call start_row(t, act, src, r, st)
            call put_text(t, 'EXTREMA', r, trim(KINDS(q)), 8, st)
            call put_text(t, 'NOEUD', r, table_entity_label(where(q)), 8, st)
            call put_text(t, 'CMP', r, src%f%components(which(q))%s, 8, st)
            call put_real(t, 'VALE', r, best(q), st)
            if (st%failed()) return
        end do
    contains
        subroutine keep(q, value)
            integer, intent(in) :: q
            real(dp), intent(in) :: value
            best(q) = value
            where(q) = nodes(i)
            which(q) = ks(j)
        end subroutine keep
    end subroutine extrema_rows

    !> MOYENNE_ARITH of a nodal field: per component, its sum over the selected nodes that
    !> hold it divided by the number of selected nodes (prmono).
    subroutine arithmetic_rows(occ, act, src, mesh, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(action_t), intent(in) :: act
        type(source_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        integer, allocatable :: nodes(:), ks(:)
        real(dp) :: total
        integer :: i, j, r
        if (src%f%location /= FIELD_NOEU) then
            call occ%error_at(field_key(src), 'MOYENNE_ARITH reads nodal fields (as in ' // &
                'Code_Aster); ' // field_label(src) // ' is ' // field_location_name(src%f), &
                st, STATUS_MODEL_ERROR)
            return
        end if
        call nodes_of_selection(occ, mesh, nodes, st)
        if (st%failed()) return
        if (size(nodes) == 0) then
            call occ%error_at('OPERATION', 'no node is selected', st)
            return
        end if
        ks = extreme_components(act, src%f)
        do j = 1, size(ks)
            total = 0.0_dp
            do i = 1, size(nodes)
                if (src%f%node_has(ks(j), nodes(i))) then
                    if (abs(src%f%node_values(ks(j), nodes(i))) > VALUE_LIMIT) then
                        call occ%error_at(field_key(src), 'component ' // &
                            src%f%components(ks(j))%s // ' of ' // field_label(src) // &
                            ' at node ' // node_name(mesh, int(nodes(i), i4)) // ' is ' // &
                            'beyond what POST_RELEVE_T sums (1E+200)', st, STATUS_MODEL_ERROR)
                        return
                    end if
                    total = total + src%f%node_values(ks(j), nodes(i))
                end if
            end do
            call start_row(t, act, src, r, st)
            call put_text(t, 'CMP', r, src%f%components(ks(j))%s, 8, st)
            call put_real(t, 'MOYENNE', r, total / size(nodes), st)
            if (st%failed()) return
        end do
    end subroutine arithmetic_rows

end module post_releve_command
