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
!> Code_Aster's catalog has it. REPERE='UTILISATEUR' (ANGL_NAUT) and 'LOCAL' on a SEGMENT
!> (x along the line, y the part of VECT_Y orthogonal to it) turn the components of DEPL,
!> SIEF_ELNO, SIGM_NOEU, SIGM_ELNO, FLUX_ELNO and FLUX_NOEU as Code_Aster's
!> crea_resu_local does (MODI_REPERE UTILISATEUR with those nautical angles; alpha alone in
!> a 2D mesh); other fields keep the global frame, with an alarm.
!> Not built, each a located error saying so: CHAM_GD, TYPE='ARC' and 'GROUP_MA', REPERE
!> POLAIRE and CYLINDRIQUE, LOCAL on a GROUP_NO, OPERATION='MOYENNE', INVARIANT,
!> ELEM_PRINCIPAUX, TRAC_NOR / TRAC_DIR, RESULTANTE, VIS_A_VIS, ELGA fields (Code_Aster
!> itself warns they are not meant for it) and element fields with sub-points (plate
!> layers: extract a layer with POST_CHAMP EXTR_COQUE first).
module macr_lign_coupe_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, real_e13
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node_group, nodes_of_group
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
    use releve_frames, only: path_abscissae, user_frame, rotate_vector, rotate_tensor
    use point_location, only: located_point_t, locate_point
    implicit none
    private
    public :: run_macr_lign_coupe

    !> One cut line: its points and title.
    type :: line_t
        character(len=:), allocatable :: label
        real(dp), allocatable :: x(:, :)            !< (3, n) the points asked for
        type(string_t), allocatable :: asked(:)     !< NOM_CMP, none: every component
        real(dp) :: distance_max = 0.0_dp
        !> REPERE UTILISATEUR / LOCAL: the components are turned by pgl (rows: the axes)
        logical :: turned = .false.
        real(dp) :: pgl(3, 3) = 0.0_dp
    end type line_t

    !> The fields whose components MACR_LIGN_COUPE turns (crea_resu_local); the others are
    !> read in the global frame with an alarm, as Code_Aster reads them.
    character(len=*), parameter :: TURNED_FIELDS = ' DEPL SIEF_ELNO SIGM_NOEU SIGM_ELNO ' // &
        'FLUX_ELNO FLUX_NOEU '
    !> Precision of Code_Aster's crea_resu_local (epsi): parallel or orthogonal axes.
    real(dp), parameter :: LOCAL_EPSILON = 1.0e-8_dp

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
                call declare_columns(cmd, f, lines, names, t, st)
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

    ! ---- the lines ---------------------------------------------------------------------

    !> Reads one LIGN_COUPE occurrence: its points, title, components and distance.
    subroutine read_line(occ, mesh, n_unnamed, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, intent(inout) :: n_unnamed
        type(line_t), intent(out) :: line
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: kind, text, group
        real(dp) :: a(3), b(3)
        integer :: n, i
        integer(i4) :: g
        integer(i4), allocatable :: nodes(:)
        call occ%get_text('TYPE', kind, st)
        if (st%failed()) return
        call refuse_unbuilt(occ, kind, st)
        if (st%failed()) return
        if (occ%has('DISTANCE_MAX')) call occ%get_real('DISTANCE_MAX', line%distance_max, st)
        if (st%ok() .and. .not. line%distance_max >= 0.0_dp) call occ%error_at( &
            'DISTANCE_MAX', 'DISTANCE_MAX is a distance: >= 0', st)
        if (st%ok() .and. occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', line%asked, st)
        if (st%failed()) return
        if (.not. allocated(line%asked)) allocate (line%asked(0))
        select case (kind)
        case ('SEGMENT')
            call check_block(occ, 'SEGMENT', 'GROUP_NO', st)
            if (st%ok() .and. .not. occ%has('NB_POINTS')) call occ%error_at('TYPE', &
                'TYPE=''SEGMENT'' needs NB_POINTS, the number of points of the line', st)
            if (st%ok()) call occ%get_int('NB_POINTS', n, st)
            if (st%ok()) call end_point(occ, mesh, 'COOR_ORIG', 'GROUP_NO_ORIG', a, st)
            if (st%ok()) call end_point(occ, mesh, 'COOR_EXTR', 'GROUP_NO_EXTR', b, st)
            if (st%failed()) return
            if (.not. norm2(b - a) > 0.0_dp) then
                call occ%error_at('NB_POINTS', 'the segment''s origin and end are the ' // &
                    'same point: the line has no direction', st)
                return
            end if
            allocate (line%x(3, n))
            do i = 1, n
                line%x(:, i) = a + (b - a) * (real(i - 1, dp) / real(n - 1, dp))
            end do
            n_unnamed = n_unnamed + 1
            line%label = 'l.coupe' // to_text(n_unnamed)
        case ('GROUP_NO')
            call check_block(occ, 'GROUP_NO', 'NB_POINTS COOR_ORIG COOR_EXTR ' // &
                'GROUP_NO_ORIG GROUP_NO_EXTR', st)
            if (st%ok() .and. .not. occ%has('GROUP_NO')) call occ%error_at('TYPE', &
                'TYPE=''GROUP_NO'' needs GROUP_NO, the ordered nodes of the line', st)
            if (st%ok()) call occ%get_text('GROUP_NO', group, st)
            if (st%failed()) return
            g = find_node_group(mesh, group, st)
            if (st%failed()) then
                call relocate_at(occ, 'GROUP_NO', st)
                return
            end if
            nodes = nodes_of_group(mesh, g)
            if (size(nodes) == 0) then
                call occ%error_at('GROUP_NO', 'group ' // group // ' has no node', st)
                return
            end if
            line%x = mesh%coords(:, nodes)
            line%label = group
        end select
        if (occ%has('INTITULE')) then
            call occ%get_text('INTITULE', text, st)
            if (st%failed()) return
            line%label = text
        end if
        call read_frame(occ, mesh, line, st)
    end subroutine read_line

    !> REPERE UTILISATEUR (ANGL_NAUT) and LOCAL (a SEGMENT's direction and VECT_Y), as
    !> Code_Aster's crea_resu_local turns them (MODI_REPERE UTILISATEUR with the nautical
    !> angles; in a 2D mesh alpha alone).
    subroutine read_frame(occ, mesh, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(line_t), intent(inout) :: line
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: frame
        real(dp), allocatable :: v(:)
        real(dp) :: angles(3), cx(3), cy(3), cz(3)
        integer :: n
        call occ%get_text('REPERE', frame, st)
        if (st%failed() .or. frame == 'GLOBAL') return
        angles = 0.0_dp
        if (frame == 'UTILISATEUR') then
            if (.not. occ%has('ANGL_NAUT')) then
                call occ%error_at('REPERE', 'REPERE=''UTILISATEUR'' needs ANGL_NAUT, the ' // &
                    'frame''s nautical angles in degrees', st)
                return
            end if
            call occ%get_reals('ANGL_NAUT', v, st)
            if (st%failed()) return
            angles = v(1:3)
        else                                            ! LOCAL on a SEGMENT
            if (.not. occ%has('VECT_Y')) then
                call occ%error_at('REPERE', 'REPERE=''LOCAL'' needs VECT_Y, the direction ' // &
                    'of the local y axis', st)
                return
            end if
            call occ%get_reals('VECT_Y', v, st)
            if (st%failed()) return
            n = size(line%x, 2)
            cx = line%x(:, n) - line%x(:, 1)
            cy = 0.0_dp
            cy(1:min(size(v), mesh%dim)) = v(1:min(size(v), mesh%dim))
            if (mesh%dim == 2) cx(3) = 0.0_dp
            cx = cx / norm2(cx)
            if (.not. norm2(cy) >= LOCAL_EPSILON) then
                call occ%error_at('VECT_Y', 'VECT_Y has no direction (its length is 0)', st)
                return
            end if
            cy = cy / norm2(cy)
            if (all(abs(cx - cy) < LOCAL_EPSILON) .or. all(abs(cx + cy) < LOCAL_EPSILON)) then
                call occ%error_at('VECT_Y', 'VECT_Y is along the line: it does not make ' // &
                    'a frame with it', st)
                return
            end if
            cz = [cx(2) * cy(3) - cx(3) * cy(2), cx(3) * cy(1) - cx(1) * cy(3), &
                  cx(1) * cy(2) - cx(2) * cy(1)]
            cz = cz / norm2(cz)
            ! VECT_Y not orthogonal to the line: its part orthogonal to it (z x x)
            cy = [cz(2) * cx(3) - cz(3) * cx(2), cz(3) * cx(1) - cz(1) * cx(3), &
                  cz(1) * cx(2) - cz(2) * cx(1)]
            if (mesh%dim == 2) then
                angles(1) = atan2(cx(2), cx(1))
            else if (cx(1)**2 + cx(2)**2 > LOCAL_EPSILON) then
                angles = [atan2(cx(2), cx(1)), -asin(cx(3)), atan2(cy(3), cz(3))]
            else
                angles = [atan2(-cy(1), cy(2)), -asin(cx(3)), 0.0_dp]
            end if
            angles = angles * (45.0_dp / atan(1.0_dp))
        end if
        if (mesh%dim == 2) angles(2:3) = 0.0_dp
        call user_frame(angles, line%pgl)
        line%turned = .true.
    end subroutine read_frame

    !> The keywords and values of LIGN_COUPE parasol does not build (module header).
    subroutine refuse_unbuilt(occ, kind, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: kind
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        character(len=*), parameter :: KEYS(7) = [character(len=15) :: 'INVARIANT', &
            'ELEM_PRINCIPAUX', 'TRAC_NOR', 'TRAC_DIR', 'RESULTANTE', 'MOMENT', 'CENTRE']
        integer :: k
        if (kind == 'ARC' .or. kind == 'GROUP_MA') then
            call occ%error_at('TYPE', 'TYPE=''' // kind // ''' is not built by parasol: ' // &
                'SEGMENT and GROUP_NO are', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call occ%get_text('REPERE', text, st)
        if (st%ok() .and. (text == 'POLAIRE' .or. text == 'CYLINDRIQUE' .or. &
            (text == 'LOCAL' .and. kind /= 'SEGMENT'))) call occ%error_at('REPERE', &
            'REPERE=''' // text // ''' is not built by MACR_LIGN_COUPE in parasol ' // &
            '(GLOBAL, UTILISATEUR, and LOCAL on a SEGMENT are)', st, STATUS_NOT_IMPLEMENTED)
        if (st%ok()) call occ%get_text('OPERATION', text, st)
        if (st%ok() .and. text /= 'EXTRACTION') call occ%error_at('OPERATION', &
            'OPERATION=''' // text // ''' is not built by MACR_LIGN_COUPE in parasol: ' // &
            'EXTRACTION is', st, STATUS_NOT_IMPLEMENTED)
        do k = 1, size(KEYS)
            if (st%failed()) return
            if (occ%has(trim(KEYS(k)))) call occ%error_at(trim(KEYS(k)), trim(KEYS(k)) // &
                ' is not built by MACR_LIGN_COUPE in parasol: the components are (NOM_CMP)', &
                st, STATUS_NOT_IMPLEMENTED)
        end do
    end subroutine refuse_unbuilt

    !> Code_Aster's blocks: keywords of another TYPE are refused.
    subroutine check_block(occ, kind, others, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: kind, others
        type(status_t), intent(inout) :: st
        integer :: a, b
        a = 1
        do while (a <= len(others) .and. st%ok())
            b = index(others(a:) // ' ', ' ') + a - 2
            if (b >= a) then
                if (occ%has(others(a:b))) call occ%error_at(others(a:b), others(a:b) // &
                    ' does not go with TYPE=''' // kind // '''', st)
            end if
            a = b + 2
        end do
    end subroutine check_block

    !> An end of a segment: coordinates (2 or 3, the third 0) or the node of a group.
    subroutine end_point(occ, mesh, coor_key, group_key, p, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: coor_key, group_key
        real(dp), intent(out) :: p(3)
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: v(:)
        character(len=:), allocatable :: group
        integer(i4), allocatable :: nodes(:)
        integer(i4) :: g
        p = 0.0_dp
        if (occ%has(coor_key) .eqv. occ%has(group_key)) then
            call occ%error_at('TYPE', 'give one of ' // coor_key // ' and ' // group_key, st)
            return
        end if
        if (occ%has(coor_key)) then
            call occ%get_reals(coor_key, v, st)
            if (st%ok() .and. size(v) == 2 .and. mesh%dim == 3) call occ%error_at(coor_key, &
                'the mesh is three-dimensional: give 3 coordinates', st)
            if (st%ok()) p(1:size(v)) = v
            return
        end if
        call occ%get_text(group_key, group, st)
        if (st%failed()) return
        g = find_node_group(mesh, group, st)
        if (st%failed()) then
            call relocate_at(occ, group_key, st)
            return
        end if
        nodes = nodes_of_group(mesh, g)
        if (size(nodes) /= 1) then
            call occ%error_at(group_key, 'group ' // group // ' has ' // &
                to_text(size(nodes, kind=i4)) // ' nodes: the end of a segment is one', st)
            return
        end if
        p = mesh%coords(:, nodes(1))
    end subroutine end_point

    ! ---- the table ---------------------------------------------------------------------

    !> The columns: the fixed ones, then the components of every line, in order.
    subroutine declare_columns(cmd, f, lines, names, t, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: f
        type(line_t), intent(in) :: lines(:)
        type(string_t), allocatable, intent(out) :: names(:)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        integer :: k, j, c
        allocate (names(0))
        do k = 1, size(lines)
            if (size(lines(k)%asked) == 0) then
                call add_names(names, held_components(f))
                cycle
            end if
            do j = 1, size(lines(k)%asked)
                if (field_component(f, lines(k)%asked(j)%s) == 0) then
                    occ = cmd%occurrence('LIGN_COUPE', k)
                    call occ%error_at('NOM_CMP', 'the field ' // &
                        'has no component ' // lines(k)%asked(j)%s // ' (it has ' // &
                        joined(held_components(f)) // ')', st)
                    return
                end if
            end do
            call add_names(names, lines(k)%asked)
        end do
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
        type(string_t), allocatable :: cmps(:)
        logical, allocatable :: candidate(:), kept(:)
        real(dp), allocatable :: absc(:), xk(:, :)
        integer, allocatable :: cols(:), ks(:)
        real(dp), allocatable :: vals(:)
        logical, allocatable :: has(:)
        logical :: turn
        integer :: i, j, r, m
        cmps = line%asked
        if (size(cmps) == 0) cmps = held_components(f)
        allocate (cols(size(cmps)), ks(size(cmps)), vals(size(cmps)), has(size(cmps)))
        turn = line%turned .and. index(TURNED_FIELDS, ' ' // nom_cham // ' ') > 0
        if (first .and. line%turned .and. .not. turn) call warn_at(ctx, occ, 'REPERE', &
            'the components of ' // nom_cham // ' are not turned by MACR_LIGN_COUPE ' // &
            '(only those of DEPL, SIEF_ELNO, SIGM_NOEU, SIGM_ELNO, FLUX_ELNO, FLUX_NOEU ' // &
            'are): they are given in the global frame, as Code_Aster gives them')
        do j = 1, size(cmps)
            ks(j) = field_component(f, cmps(j)%s)
            do m = 1, t%n_columns
                if (t%columns(m)%name == cmps(j)%s) cols(j) = m
            end do
        end do
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
        xk = line%x(:, pack([(i, i=1, size(kept))], kept))
        absc = path_abscissae(xk)
        m = 0
        do i = 1, size(kept)
            if (.not. kept(i)) cycle
            m = m + 1
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
            do j = 1, size(cmps)
                call value_at(mesh, f, loc(i), ks(j), vals(j), has(j))
            end do
            if (turn) call turn_values(mesh, f, loc(i), nom_cham, line%pgl, cmps, vals, has)
            do j = 1, size(cmps)
                if (has(j)) call table_set_real(t, cols(j), r, vals(j), st)
            end do
            if (st%failed()) return
        end do
    end subroutine line_rows

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

    !> The components of a vector (DX DY DZ, DRX DRY DRZ, FLUX FLUY FLUZ) or a tensor
    !> (SIXX .. SIYZ) turned: P v, P S P^T (a component the point lacks counts 0).
    subroutine turn_values(mesh, f, loc, nom_cham, pgl, cmps, vals, has)
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(in) :: f
        type(located_point_t), intent(in) :: loc
        character(len=*), intent(in) :: nom_cham
        real(dp), intent(in) :: pgl(3, 3)
        type(string_t), intent(in) :: cmps(:)
        real(dp), intent(inout) :: vals(:)
        logical, intent(in) :: has(:)
        if (nom_cham == 'DEPL') then
            call turn_group([character(len=4) :: 'DX', 'DY', 'DZ'])
            call turn_group([character(len=4) :: 'DRX', 'DRY', 'DRZ'])
        else if (nom_cham(1:4) == 'FLUX') then
            call turn_group([character(len=4) :: 'FLUX', 'FLUY', 'FLUZ'])
        else
            call turn_group([character(len=4) :: 'SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', &
                             'SIYZ'])
        end if
    contains
        subroutine turn_group(names)
            character(len=4), intent(in) :: names(:)
            real(dp) :: g(size(names)), turned(size(names))
            logical :: present
            integer :: k, j, kf
            do k = 1, size(names)
                g(k) = 0.0_dp
                kf = field_component(f, trim(names(k)))
                if (kf > 0) call value_at(mesh, f, loc, kf, g(k), present)
                if (kf > 0 .and. .not. present) g(k) = 0.0_dp
            end do
            if (size(names) == 3) then
                turned = rotate_vector(pgl, g)
            else
                turned = rotate_tensor(pgl, g)
            end if
            do j = 1, size(cmps)
                do k = 1, size(names)
                    if (has(j) .and. cmps(j)%s == trim(names(k))) vals(j) = turned(k)
                end do
            end do
        end subroutine turn_group
    end subroutine turn_values

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
