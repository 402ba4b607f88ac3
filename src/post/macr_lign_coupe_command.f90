!> MACR_LIGN_COUPE (U4.81.13): a table of the values of a result's field at points along
!> cut lines. Code_Aster's macro makes a mesh of the line's points, projects the field on
!> it (PROJ_CHAMP METHODE='COLLOCATION', TYPE_CHAM='NOEU': in the cell holding a point,
!> the field interpolated with the cell's shape functions; an ELNO field from the values
!> of that cell at its nodes) and reads it there by POST_RELEVE_T EXTRACTION, then drops
!> the columns RESU and NOEUD. parasol computes the same values directly:
!>  - the points: TYPE='SEGMENT' NB_POINTS points evenly spaced from COOR_ORIG (or the
!>    node of GROUP_NO_ORIG) to COOR_EXTR (or GROUP_NO_EXTR), both ends included;
!>    TYPE='GROUP_NO' the nodes of the group in its order (a NOEUD_ORDO path);
!>  - each point located in the cells of the highest dimension that carry the field
!>    (point_location); a point farther than DISTANCE_MAX (default 0: on a cell) from
!>    every cell is outside the matter and left out, with an alarm, as crea_grp_matiere
!>    leaves it out; ABSC_CURV runs along the points kept;
!>  - the columns: INTITULE (given, else the group's name, else 'l.coupe<i>' counting the
!>    lines that are not groups), NOM_CHAM, NUME_ORDRE, INST, ABSC_CURV, COOR_X, COOR_Y,
!>    COOR_Z, then the components (NOM_CMP, else every one the field holds: TOUT_CMP);
!>    rows by line, then instant (NUME_ORDRE / INST / LIST_INST, all by default), then
!>    point.
!> NOM_CHAM defaults to SIGM_NOEU for a mechanical result and TEMP for a thermal one, as
!> Code_Aster's catalog has it. REPERE UTILISATEUR, LOCAL (on a SEGMENT or a GROUP_NO path),
!> CYLINDRIQUE and POLAIRE turn the components of DEPL, SIEF_ELNO, SIGM_NOEU, SIGM_ELNO,
!> FLUX_ELNO and FLUX_NOEU as Code_Aster's crea_resu_local does (lign_coupe_frames); other
!> fields keep the global frame, with an alarm. INVARIANT, ELEM_PRINCIPAUX, TRAC_NOR and
!> TRAC_DIR are computed at each point as POST_RELEVE_T computes them on the line's mesh
!> (releve_frames' kernels).
!> Not built, each a located error saying so: CHAM_GD, TYPE='ARC' and 'GROUP_MA',
!> OPERATION='MOYENNE', RESULTANTE, VIS_A_VIS, ELGA fields (Code_Aster itself warns they
!> are not meant for it) and element fields with sub-points (plate layers: extract a layer
!> with POST_CHAMP EXTR_COQUE first).
module macr_lign_coupe_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, real_e13
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use mesh_cell_shapes, only: CELL_TYPE_DIM, CELL_TYPE_NODES
    use field_types, only: field_t, FIELD_NOEU, FIELD_ELNO, field_component, &
        field_position, field_location_name
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use result_instants, only: selected_instants
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_int, table_set_real, table_set_text, TABLE_INT, TABLE_REAL, TABLE_TEXT
    use table_keywords, only: relocate_at, warn_at
    use crea_table_command, only: result_of_occurrence
    use releve_frames, only: path_abscissae, user_frame, plane_local_frames, polar_frame, &
        tensor_invariants, principal_stresses, value_kind, tensor_row, turned_value, &
        traction, KIND_VECTOR, KIND_TENSOR, VECTOR_CMPS, TENSOR_SLOT_NAMES
    use lign_coupe_frames, only: path_local_angles, cylinder_frame, turn_point
    use point_location, only: located_point_t, locate_point
    use lign_coupe_lines, only: line_t, read_line, Q_COMPONENTS, Q_INVARIANTS, Q_PRINCIPAL, &
        Q_TRAC_NOR, Q_TRAC_DIR, CUBE_LIMIT, INVARIANT_NAMES, PRINCIPAL_NAMES, TURNED_FIELDS
    implicit none
    private
    public :: run_macr_lign_coupe


contains

    !> Handler of MACR_LIGN_COUPE.
    subroutine run_macr_lign_coupe(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(result_fields_t), pointer :: res
        type(mesh_t), pointer :: mesh
        type(field_t), pointer :: f
        type(table_t), allocatable :: t
        type(line_t), allocatable :: lines(:)
        type(string_t), allocatable :: names(:)
        character(len=:), allocatable :: nom_cham
        integer, allocatable :: indices(:)
        logical :: by_inst
        integer :: k, j, n_unnamed
        if (cmd%has('CHAM_GD')) then
            call cmd%error_at('CHAM_GD', 'MACR_LIGN_COUPE reads the fields of a result ' // &
                '(RESULTAT) in parasol; put the field in a result with CREA_RESU', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (cmd%has('VIS_A_VIS')) then
            call cmd%error_at('VIS_A_VIS', 'VIS_A_VIS (the cells a line crosses chosen ' // &
                'by group) is not built by parasol', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call result_of_occurrence(cmd, res, st)
        if (st%failed()) return
        if (cmd%has('NOM_CHAM')) then
            call cmd%get_text('NOM_CHAM', nom_cham, st)
            if (st%failed()) return
        else if (res%type_name() == 'evol_ther') then
            nom_cham = 'TEMP'                  ! Code_Aster's default for evol_ther
        else
            nom_cham = 'SIGM_NOEU'             ! Code_Aster's default for mechanics
        end if
        call selected_instants(cmd, res, indices, by_inst, st)
        if (st%ok()) call result_mesh(res, mesh, st)
        if (st%failed()) then
            call relocate_at(cmd, 'RESULTAT', st)
            return
        end if
        allocate (lines(cmd%count('LIGN_COUPE')))
        n_unnamed = 0
        do k = 1, size(lines)
            call read_line(cmd%occurrence('LIGN_COUPE', k), mesh, n_unnamed, lines(k), st)
            if (st%failed()) return
        end do
        allocate (t)
        call table_init(t)
        do j = 1, size(indices)
            call result_field_at(res, int(indices(j), i4), nom_cham, f, st)
            if (st%failed()) then
                call relocate_at(cmd, merge('NOM_CHAM', 'RESULTAT', cmd%has('NOM_CHAM')), st)
                return
            end if
            call check_field(cmd, f, nom_cham, st)
            if (st%failed()) return
            if (j == 1) then
                call declare_columns(cmd, f, nom_cham, lines, names, t, st)
                if (st%failed()) return
            end if
        end do
        do k = 1, size(lines)
            do j = 1, size(indices)
                call result_field_at(res, int(indices(j), i4), nom_cham, f, st)
                if (st%failed()) return
                call line_rows(ctx, cmd%occurrence('LIGN_COUPE', k), mesh, f, lines(k), &
                    nom_cham, res%nume_ordre(indices(j)), res%inst(indices(j)), j == 1, &
                    t, st)
                if (st%failed()) return
            end do
        end do
        call ctx%write_mess('    MACR_LIGN_COUPE: ' // to_text(int(t%n_rows, i4)) // &
            ' rows, ' // to_text(int(t%n_columns, i4)) // ' columns')
        call move_alloc(t, result)
    end subroutine run_macr_lign_coupe

    !> The field must be nodal or at the nodes of cells without sub-points.
    subroutine check_field(cmd, f, nom_cham, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: nom_cham
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: key
        key = merge('NOM_CHAM', 'RESULTAT', cmd%has('NOM_CHAM'))
        if (f%location /= FIELD_NOEU .and. f%location /= FIELD_ELNO) then
            call cmd%error_at(key, 'MACR_LIGN_COUPE interpolates nodal (NOEU) and ' // &
                'element-node (ELNO) fields; ' // nom_cham // ' is ' // &
                field_location_name(f) // ' (compute its _ELNO or _NOEU form with ' // &
                'CALC_CHAMP)', st, STATUS_NOT_IMPLEMENTED)
        else if (f%location == FIELD_ELNO) then
            if (any(f%n_subpoints > 1 .and. f%n_points > 0)) call cmd%error_at(key, &
                nom_cham // ' has sub-points (plate layers): extract one with POST_CHAMP ' // &
                'EXTR_COQUE (NUME_COUCHE, NIVE_COUCHE) and cut that result', st, &
                STATUS_NOT_IMPLEMENTED)
        end if
    end subroutine check_field


    ! ---- the table ---------------------------------------------------------------------

    !> The columns: the fixed ones, then (in POST_RELEVE_T's rvpara order) the components
    !> of every line, the invariants, the principal values, the tractions.
    subroutine declare_columns(cmd, f, nom_cham, lines, names, t, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: nom_cham
        type(line_t), intent(in) :: lines(:)
        type(string_t), allocatable, intent(out) :: names(:)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: outs(:), nor(:), dir(:)
        logical :: invariants, principal
        integer :: k, c
        allocate (names(0), nor(0), dir(0))
        invariants = .false.
        principal = .false.
        do k = 1, size(lines)
            call line_outputs(cmd%occurrence('LIGN_COUPE', k), lines(k), f, nom_cham, outs, st)
            if (st%failed()) return
            select case (lines(k)%quantity)
            case (Q_COMPONENTS)
                call add_names(names, outs)
            case (Q_INVARIANTS)
                invariants = .true.
            case (Q_PRINCIPAL)
                principal = .true.
            case (Q_TRAC_NOR)
                call add_names(nor, outs)
            case (Q_TRAC_DIR)
                call add_names(dir, outs)
            end select
        end do
        if (invariants) call add_names(names, split_words(INVARIANT_NAMES))
        if (principal) call add_names(names, split_words(PRINCIPAL_NAMES))
        call add_names(names, nor)
        call add_names(names, dir)
        call table_add_column(t, 'INTITULE', TABLE_TEXT, c, st, 16)
        call table_add_column(t, 'NOM_CHAM', TABLE_TEXT, c, st, 16)
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c, st)
        call table_add_column(t, 'INST', TABLE_REAL, c, st)
        call table_add_column(t, 'ABSC_CURV', TABLE_REAL, c, st)
        call table_add_column(t, 'COOR_X', TABLE_REAL, c, st)
        call table_add_column(t, 'COOR_Y', TABLE_REAL, c, st)
        call table_add_column(t, 'COOR_Z', TABLE_REAL, c, st)
        do k = 1, size(names)
            if (st%ok()) call table_add_column(t, names(k)%s, TABLE_REAL, c, st)
        end do
    end subroutine declare_columns

    !> The quantities a line writes (POST_RELEVE_T's rvcpnc on the line): the components
    !> asked (NOM_CMP, else all the field holds; in the POLAIRE frame those it turns, in
    !> the quantity's order), VMIS .. DETER, PRIN_1 .. VECT_3_Z, TRAC_NOR or TR_NOR_1..3,
    !> TRAC_DIR or TR_DIR_1..3.
    subroutine line_outputs(occ, line, f, nom_cham, outs, st)
        type(keyword_set_t), intent(in) :: occ
        type(line_t), intent(in) :: line
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: nom_cham
        type(string_t), allocatable, intent(out) :: outs(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: asked(:)
        character(len=:), allocatable :: key
        integer :: kind, slots, j
        allocate (outs(0))
        kind = value_kind(f%quantity)
        slots = tensor_row(f)
        if (kind == KIND_TENSOR .and. (slots < 1 .or. slots > 2)) kind = 0
        asked = line%asked
        if (size(asked) == 0) asked = held_components(f)
        do j = 1, size(asked)
            if (field_component(f, asked(j)%s) == 0) then
                call occ%error_at('NOM_CMP', 'the field has no component ' // asked(j)%s // &
                    ' (it has ' // joined(held_components(f)) // ')', st)
                return
            end if
        end do
        select case (line%quantity)
        case (Q_COMPONENTS)
            if (.not. (line%frame == 'POLAIRE' .and. turns(line, nom_cham))) then
                outs = asked
                return
            end if
            do j = 1, 6
                if (kind == KIND_VECTOR) then
                    if (listed(asked, VECTOR_CMPS(j))) outs = [outs, string_t(trim(VECTOR_CMPS(j)))]
                else if (kind == KIND_TENSOR) then
                    if (listed(asked, TENSOR_SLOT_NAMES(j, slots))) outs = [outs, &
                        string_t(trim(TENSOR_SLOT_NAMES(j, slots)))]
                end if
            end do
            if (size(outs) == 0) call occ%error_at('REPERE', 'REPERE=''POLAIRE'' turns ' // &
                'displacements (DX .. DRZ) and stress tensors (SIXX .. SIYZ); none of ' // &
                joined(asked) // ' is one', st)
        case (Q_INVARIANTS, Q_PRINCIPAL)
            key = trim(merge('INVARIANT      ', 'ELEM_PRINCIPAUX', line%quantity == Q_INVARIANTS))
            if (kind /= KIND_TENSOR) then
                call occ%error_at(key, 'the invariants and principal values are those of a ' // &
                    'stress or strain tensor (SIXX .. SIYZ, EPXX .. EPYZ); the field ' // &
                    'holds none (' // f%quantity // ')', st)
                return
            end if
            if (line%quantity == Q_INVARIANTS) then
                outs = split_words(INVARIANT_NAMES)
            else
                outs = split_words(PRINCIPAL_NAMES)
            end if
        case (Q_TRAC_NOR, Q_TRAC_DIR)
            key = trim(merge('TRAC_NOR', 'TRAC_DIR', line%quantity == Q_TRAC_NOR))
            if (kind == KIND_VECTOR) then
                outs = [string_t(key)]
            else if (kind == KIND_TENSOR) then
                outs = split_words(merge('TR_NOR_1 TR_NOR_2 TR_NOR_3', &
                                         'TR_DIR_1 TR_DIR_2 TR_DIR_3', line%quantity == Q_TRAC_NOR))
            else
                call occ%error_at(key, 'a traction is that of a displacement-like vector or ' // &
                    'of a stress tensor; the field is neither (' // f%quantity // ')', st)
            end if
        end select
    end subroutine line_outputs

    !> Whether the line's frame turns this field (crea_resu_local's fields).
    pure logical function turns(line, nom_cham)
        type(line_t), intent(in) :: line
        character(len=*), intent(in) :: nom_cham
        turns = line%frame /= 'GLOBAL' .and. index(TURNED_FIELDS, ' ' // nom_cham // ' ') > 0
    end function turns

    !> The rows of one line for one field.
    subroutine line_rows(ctx, occ, mesh, f, line, nom_cham, nume_ordre, inst, first, t, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(in) :: f
        type(line_t), intent(in) :: line
        character(len=*), intent(in) :: nom_cham
        integer(i4), intent(in) :: nume_ordre
        real(dp), intent(in) :: inst
        logical, intent(in) :: first
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(located_point_t), allocatable :: loc(:)
        type(string_t), allocatable :: outs(:)
        logical, allocatable :: candidate(:), kept(:), hv(:)
        real(dp), allocatable :: absc(:), xk(:, :), v(:), tangent(:, :), normal(:, :), &
            local_angles(:, :)
        integer, allocatable :: cols(:), ks(:), along(:)
        real(dp) :: q(12)
        logical :: qhas(12), turn, ok
        integer :: i, j, r, m, bad
        call line_outputs(occ, line, f, nom_cham, outs, st)
        if (st%failed()) return
        turn = turns(line, nom_cham)
        if (first .and. line%frame /= 'GLOBAL' .and. .not. turn) call warn_at(ctx, occ, &
            'REPERE', 'the components of ' // nom_cham // ' are not turned by ' // &
            'MACR_LIGN_COUPE (only those of DEPL, SIEF_ELNO, SIGM_NOEU, SIGM_ELNO, ' // &
            'FLUX_ELNO, FLUX_NOEU are): they are given in the global frame, as Code_Aster ' // &
            'gives them')
        allocate (cols(size(outs)))
        do j = 1, size(outs)
            do m = 1, t%n_columns
                if (t%columns(m)%name == outs(j)%s) cols(j) = m
            end do
        end do
        ks = [(j, j=1, size(f%components))]
        if (size(line%asked) > 0) ks = [(field_component(f, line%asked(j)%s), &
                                         j=1, size(line%asked))]
        call carrying_cells(mesh, f, ks, candidate)
        allocate (loc(size(line%x, 2)), kept(size(line%x, 2)))
        do i = 1, size(line%x, 2)
            call locate_point(mesh, candidate, line%x(:, i), line%distance_max, loc(i))
            kept(i) = loc(i)%cell > 0
        end do
        if (.not. any(kept)) then
            call occ%error_at('TYPE', 'no point of the line is in the matter: none is ' // &
                'within DISTANCE_MAX=' // real_e13(line%distance_max) // ' of a cell ' // &
                'carrying ' // nom_cham // ' (first point ' // point_text(line%x(:, 1)) // &
                ')', st)
            return
        end if
        if (first .and. .not. all(kept)) call warn_at(ctx, occ, 'TYPE', &
            to_text(int(count(.not. kept), i4)) // ' of the ' // &
            to_text(size(kept, kind=i4)) // ' points of line ' // line%label // &
            ' are outside the matter (farther than DISTANCE_MAX from the cells): they ' // &
            'are left out of the table, as Code_Aster leaves them out')
        along = pack([(i, i=1, size(kept))], kept)
        xk = line%x(:, along)
        absc = path_abscissae(xk)
        if (line%frame == 'POLAIRE' .or. line%quantity == Q_TRAC_NOR) then
            if (.not. in_one_plane(xk)) then
                if (line%quantity == Q_TRAC_NOR) then
                    call occ%error_at('TRAC_NOR', 'TRAC_NOR takes the normal of the line ' // &
                        'in its plane: the points must lie in one plane z = constant', st)
                    return
                end if
                if (first) call warn_at(ctx, occ, 'REPERE', 'the POLAIRE frame is that of ' // &
                    'points in one plane z = constant; those of line ' // line%label // &
                    ' are not: no row for it (Code_Aster''s alarm POSTRELE_28)')
                return
            end if
        end if
        if (line%quantity == Q_TRAC_NOR) then
            allocate (tangent(2, size(along)), normal(2, size(along)))
            call plane_local_frames(xk, tangent, normal, ok)
            if (.not. ok) then
                call occ%error_at('TRAC_NOR', 'two consecutive points of the line are at ' // &
                    'the same place: the line has no normal there', st, STATUS_MODEL_ERROR)
                return
            end if
        end if
        if (turn .and. line%frame == 'LOCAL' .and. line%kind == 'GROUP_NO') then
            allocate (local_angles(3, size(line%x, 2)))
            call path_local_angles(line%x, line%vect_y, mesh%dim, local_angles, bad)
            if (bad > 0) then
                call occ%error_at('REPERE', 'the local frame of point ' // &
                    point_text(line%x(:, bad)) // ' of line ' // line%label // ' has no ' // &
                    'direction: its segments have no length in the xy plane' // &
                    trim(merge(', or VECT_Y is along them', '                         ', &
                    mesh%dim == 3)), st, STATUS_MODEL_ERROR)
                return
            end if
        end if
        allocate (v(size(f%components)), hv(size(f%components)))
        do m = 1, size(along)
            i = along(m)
            do j = 1, size(f%components)
                call value_at(mesh, f, loc(i), j, v(j), hv(j))
            end do
            if (turn .and. line%frame /= 'POLAIRE') then
                call turn_to_frame(i, st)
                if (st%failed()) return
            end if
            call table_add_rows(t, 1)
            r = t%n_rows
            call table_set_text(t, 1, r, line%label(1:min(len(line%label), 16)), st)
            call table_set_text(t, 2, r, nom_cham, st)
            call table_set_int(t, 3, r, int(nume_ordre, i8), st)
            call table_set_real(t, 4, r, inst, st)
            call table_set_real(t, 5, r, absc(m), st)
            call table_set_real(t, 6, r, line%x(1, i), st)
            call table_set_real(t, 7, r, line%x(2, i), st)
            call table_set_real(t, 8, r, line%x(3, i), st)
            call point_quantities(m, i, ok, st)
            if (st%failed()) return
            if (ok) then
                do j = 1, size(outs)
                    if (qhas(j)) call table_set_real(t, cols(j), r, q(j), st)
                end do
            end if
            if (st%failed()) return
        end do
    contains
        !> MODI_REPERE's turn of point i (UTILISATEUR, LOCAL, CYLINDRIQUE).
        subroutine turn_to_frame(i, st)
            integer, intent(in) :: i
            type(status_t), intent(inout) :: st
            real(dp) :: pgl(3, 3), angles(3)
            logical :: on_axis
            on_axis = .false.
            select case (line%frame)
            case ('CYLINDRIQUE')
                call cylinder_frame(line%x, i, line%origin, line%axis, mesh%dim, pgl, ok)
                on_axis = .not. ok
            case ('LOCAL')
                angles = line%angles
                if (line%kind == 'GROUP_NO') angles = local_angles(:, i)
                if (mesh%dim == 2) angles(2:3) = 0.0_dp
                call user_frame(angles, pgl)
            case default                                       ! UTILISATEUR
                angles = line%angles
                if (mesh%dim == 2) angles(2:3) = 0.0_dp
                call user_frame(angles, pgl)
            end select
            if (on_axis) then
                call occ%error_at('ORIGINE', 'point ' // point_text(line%x(:, i)) // &
                    ' of line ' // line%label // ' is on the axis of the cylindrical ' // &
                    'frame, and so is the middle of its segment: it has no radial direction', &
                    st, STATUS_MODEL_ERROR)
                return
            end if
            call turn_point(f%components, v, hv, pgl, line%frame == 'CYLINDRIQUE', mesh%dim)
        end subroutine turn_to_frame

        !> q(1:size(outs)) at kept point m (point i of the line), qhas where the point
        !> holds it. ok false: nothing to write.
        subroutine point_quantities(m, i, ok, st)
            integer, intent(in) :: m, i
            logical, intent(out) :: ok
            type(status_t), intent(inout) :: st
            real(dp) :: c(6), a(2), b(2), vp(3), vecs(3, 3)
            integer :: kind, slots, j, k
            logical :: any_held
            q = 0.0_dp
            qhas = .true.
            kind = value_kind(f%quantity)
            slots = tensor_row(f)
            call canonical(kind, slots, c, any_held)
            ok = .true.
            select case (line%quantity)
            case (Q_COMPONENTS)
                do j = 1, size(outs)
                    k = field_component(f, outs(j)%s)
                    qhas(j) = hv(k)
                    if (.not. hv(k)) cycle
                    q(j) = v(k)
                    if (line%frame == 'POLAIRE' .and. turn) then
                        call polar_frame(line%x(1, i), line%x(2, i), a, b)
                        b = -b                                  ! rvcalq's orthoradial sign
                        q(j) = turned_value(kind, slot_of(kind, slots, outs(j)%s), c, a, b)
                    end if
                end do
            case (Q_INVARIANTS)
                ok = any_held
                if (.not. ok) return
                if (any(abs(c) > CUBE_LIMIT)) then
                    call occ%error_at('INVARIANT', 'the tensor reaches ' // &
                        real_e13(maxval(abs(c))) // ' at point ' // point_text(line%x(:, i)) // &
                        ': its determinant (DETER) is beyond double precision (the ' // &
                        'components stay below 1E+100)', st, STATUS_MODEL_ERROR)
                    return
                end if
                call tensor_invariants(c, q(1), q(2), q(3), q(4))
            case (Q_PRINCIPAL)
                ok = any_held
                if (.not. ok) return
                call principal_stresses(c, vp, vecs)
                q(1:3) = vp
                q(4:6) = vecs(:, 1)
                q(7:9) = vecs(:, 2)
                q(10:12) = vecs(:, 3)
            case (Q_TRAC_DIR)
                ok = any_held
                if (ok) call traction(kind, c, line%direction, q(1:size(outs)))
            case (Q_TRAC_NOR)
                ok = any_held
                if (ok) call traction(kind, c, [normal(1, m), normal(2, m), 0.0_dp], &
                                      q(1:size(outs)))
            end select
        end subroutine point_quantities

        !> The point's vector (DX .. DRZ) or tensor (xx yy zz xy xz yz) in POST_RELEVE_T's
        !> order, a component it lacks 0.
        subroutine canonical(kind, slots, c, any_held)
            integer, intent(in) :: kind, slots
            real(dp), intent(out) :: c(6)
            logical, intent(out) :: any_held
            integer :: j, k
            c = 0.0_dp
            any_held = .false.
            do j = 1, 6
                k = 0
                if (kind == KIND_VECTOR) k = field_component(f, trim(VECTOR_CMPS(j)))
                if (kind == KIND_TENSOR .and. slots >= 1) &
                    k = field_component(f, trim(TENSOR_SLOT_NAMES(j, slots)))
                if (k == 0) cycle
                if (.not. hv(k)) cycle
                c(j) = v(k)
                any_held = .true.
            end do
        end subroutine canonical
    end subroutine line_rows

    !> The place of a component in the vector or tensor order (0: neither).
    pure integer function slot_of(kind, slots, name) result(j)
        integer, intent(in) :: kind, slots
        character(len=*), intent(in) :: name
        do j = 1, 6
            if (kind == KIND_VECTOR) then
                if (trim(VECTOR_CMPS(j)) == name) return
            else if (slots >= 1) then
                if (trim(TENSOR_SLOT_NAMES(j, slots)) == name) return
            end if
        end do
        j = 0
    end function slot_of

    !> All the points in one plane z = constant (POST_RELEVE_T's rvegal, 1e-3 relative).
    pure logical function in_one_plane(x)
        real(dp), intent(in) :: x(:, :)
        real(dp) :: threshold
        integer :: i
        threshold = 1.0e-3_dp
        if (abs(x(3, 1)) >= 1.0e-3_dp) threshold = threshold * abs(x(3, 1))
        in_one_plane = .true.
        do i = 2, size(x, 2)
            if (.not. abs(x(3, 1) - x(3, i)) < threshold) in_one_plane = .false.
        end do
    end function in_one_plane

    pure logical function listed(list, name)
        type(string_t), intent(in) :: list(:)
        character(len=*), intent(in) :: name
        integer :: k
        listed = .false.
        do k = 1, size(list)
            if (list(k)%s == trim(name)) listed = .true.
        end do
    end function listed

    function split_words(text) result(words)
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: words(:)
        integer :: a, b
        allocate (words(0))
        a = 1
        do while (a <= len(text))
            if (text(a:a) == ' ') then
                a = a + 1
                cycle
            end if
            b = index(text(a:) // ' ', ' ') + a - 2
            words = [words, string_t(text(a:b))]
            a = b + 2
        end do
    end function split_words

    !> The cells a point may fall in: those of the highest dimension carrying one of the
    !> components (a NOEU field: at every node of the cell; ELNO: held by the cell).
    subroutine carrying_cells(mesh, f, ks, candidate)
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(in) :: f
        integer, intent(in) :: ks(:)
        logical, allocatable, intent(out) :: candidate(:)
        integer(i4) :: c, j, top
        integer :: q
        allocate (candidate(mesh%n_cells), source=.false.)
        do c = 1, mesh%n_cells
            do q = 1, size(ks)
                if (f%location == FIELD_NOEU) then
                    candidate(c) = candidate(c) .or. all(f%node_has(ks(q), &
                        mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)))
                else if (c <= f%n_cells) then
                    candidate(c) = candidate(c) .or. field_position(f, c, 1_i4, 1_i4, &
                        int(ks(q), i4)) > 0
                end if
            end do
        end do
        top = 0
        do c = 1, mesh%n_cells
            if (candidate(c)) top = max(top, CELL_TYPE_DIM(mesh%cell_type(c)))
        end do
        do c = 1, mesh%n_cells
            j = CELL_TYPE_DIM(mesh%cell_type(c))
            if (j /= top) candidate(c) = .false.
        end do
    end subroutine carrying_cells

    !> Component k of the field at a located point: sum of N_i times the value at node i
    !> of the cell (NOEU: the node's; ELNO: the cell's at that node).
    subroutine value_at(mesh, f, loc, k, v, has)
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(in) :: f
        type(located_point_t), intent(in) :: loc
        integer, intent(in) :: k
        real(dp), intent(out) :: v
        logical, intent(out) :: has
        integer(i4) :: i, node, nn
        integer(i8) :: pos
        v = 0.0_dp
        has = .false.
        nn = CELL_TYPE_NODES(mesh%cell_type(loc%cell))
        do i = 1, nn
            node = mesh%cell_nodes(mesh%cell_ptr(loc%cell) + i - 1)
            if (f%location == FIELD_NOEU) then
                if (.not. f%node_has(k, node)) return
                v = v + loc%shape(i) * f%node_values(k, node)
            else
                pos = field_position(f, loc%cell, i, 1_i4, int(k, i4))
                if (pos == 0) return
                v = v + loc%shape(i) * f%values(pos)
            end if
        end do
        has = .true.
    end subroutine value_at

    !> The components the field holds somewhere, in its quantity's order.
    function held_components(f) result(names)
        type(field_t), intent(in) :: f
        type(string_t), allocatable :: names(:)
        logical, allocatable :: held(:)
        integer :: k, s
        allocate (held(size(f%components)), source=.false.)
        if (f%location == FIELD_NOEU) then
            held = any(f%node_has, dim=2)
        else
            do s = 1, size(f%sets)
                if (.not. any(f%cell_set == s .and. f%n_points > 0)) cycle
                do k = 1, size(f%sets(s)%cmp)
                    held(f%sets(s)%cmp(k)) = .true.
                end do
            end do
        end if
        names = pack(f%components, held)
    end function held_components

    subroutine add_names(list, more)
        type(string_t), allocatable, intent(inout) :: list(:)
        type(string_t), intent(in) :: more(:)
        integer :: k, j
        logical :: seen
        do k = 1, size(more)
            seen = .false.
            do j = 1, size(list)
                if (list(j)%s == more(k)%s) seen = .true.
            end do
            if (.not. seen) list = [list, more(k)]
        end do
    end subroutine add_names

    function joined(names) result(text)
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(names)
            if (k > 1) text = text // ', '
            text = text // names(k)%s
        end do
    end function joined

    function point_text(p) result(text)
        real(dp), intent(in) :: p(3)
        character(len=:), allocatable :: text
        text = '(' // real_e13(p(1)) // ', ' // real_e13(p(2)) // ', ' // real_e13(p(3)) // ')'
    end function point_text

end module macr_lign_coupe_command
