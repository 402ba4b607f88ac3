!> Command handler of element characteristics: AFFE_CARA_ELEM (doc/deck-language.md):
!> COQUE, DISCRET, DISCRET_2D, ORIENTATION, then RIGI_PARASOL (which overrides the
!> discrete values of its springs).
module cara_elem_commands
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, to_upper
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cells_of_group
    use mesh_command_support, only: relocate_error, read_groups, group_cells
    use model_concept, only: model_concept_t
    use model_types, only: is_plate, ELEM_DKQ
    use model_cara_elem, only: cara_elem_init, assign_coque, assign_discrete, &
        assign_orientation, parse_cara, CARA_K_T_D_L, CARA_K_T_D_N, assign_massif, &
        MASSIF_ANGL_REP, MASSIF_ANGL_EULER, MASSIF_AXE
    use model_rigi_parasol, only: rigi_parasol_table_t, compute_rigi_parasol, &
        apply_rigi_parasol, rigi_parasol_lines, cell_centre_distances, raft_from_groups, &
        parasol_centre
    use function_concept, only: function_concept_t
    use model_parasol_function, only: distance_function_values
    use cara_elem_concept, only: cara_elem_concept_t
    implicit none
    private

    public :: run_affe_cara_elem

contains

    !> AFFE_CARA_ELEM(MODELE, COQUE, DISCRET, DISCRET_2D, ORIENTATION, MASSIF, RIGI_PARASOL,
    !> INFO).
    !> INFO=2 writes the RIGI_PARASOL table to the .mess:
    !> `RIGI_PARASOL <cell> <node> <weight> <k1> <k2> [<k3>]`, then the sum of the weights.
    !>  result : out, a cara_elem_concept_t
    !>  st     : out, located at the keyword (AFFE_CARA_ELEM/FACTOR/KEY): a group missing in
    !>           the mesh, EPAIS <= 0, a cell whose element does not fit the factor or
    !>           CARA, a wrong VALE count, RIGI_PARASOL raft nodes and springs that do not
    !>           pair one to one, FONC_GROUP without a centre
    subroutine run_affe_cara_elem(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(cara_elem_concept_t), allocatable :: cc
        class(concept_t), pointer :: p
        integer(i4) :: i, info
        logical :: verify
        call cmd%get_concept('MODELE', p, st)
        if (st%failed()) return
        select type (p)
        type is (model_concept_t)
            call cmd%get_int('INFO', info, st)
            if (st%failed()) return
            ! VERIF='MAILLE': a cell of a COQUE or DISCRET group without a plate or a
            ! discrete element is an error (Code_Aster's vafcar); without it such cells are
            ! passed over
            verify = cmd%given('VERIF')
            allocate (cc)
            call cara_elem_init(cc%cara, p%mesh)
            do i = 1, cmd%count('COQUE')
                call coque_occurrence(ctx, cmd%occurrence('COQUE', i), p, cc, verify, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('DISCRET')
                call discrete_occurrence(ctx, cmd%occurrence('DISCRET', i), 'DISCRET', p, cc, &
                                         verify, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('DISCRET_2D')
                call discrete_occurrence(ctx, cmd%occurrence('DISCRET_2D', i), 'DISCRET_2D', &
                                         p, cc, verify, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('ORIENTATION')
                call orientation_occurrence(cmd%occurrence('ORIENTATION', i), p, cc, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('MASSIF')
                call massif_occurrence(ctx, cmd%occurrence('MASSIF', i), p, cc, st)
                if (st%failed()) return
            end do
            cc%n_parasol = cmd%count('RIGI_PARASOL')
            allocate (cc%parasol(cc%n_parasol))
            do i = 1, cc%n_parasol
                call parasol_occurrence(cmd%occurrence('RIGI_PARASOL', i), p, cc%parasol(i), &
                                        cc, st)
                if (st%failed()) return
                call write_parasol(ctx, p%mesh, cc%parasol(i), info)
            end do
        class default
            call cmd%error_at('MODELE', 'expected a model (modele), got ' // p%type_name(), st)
            return
        end select
        call move_alloc(cc, result)
    end subroutine run_affe_cara_elem

    ! COQUE: EPAIS (> 0), COEF_RIGI_DRZ, the user frame (ANGL_REP, VECTEUR), COQUE_NCOU and
    ! EXCENTREMENT on the plate cells of each group. Cells without a plate element are
    ! passed over unless VERIF (a note in the .mess says how many).
    subroutine coque_occurrence(ctx, occ, mc, cc, verify, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(cara_elem_concept_t), intent(inout) :: cc
        logical, intent(in) :: verify
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:)
        integer(i4) :: skipped
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:)
        real(dp) :: epais, drz, direction(3), offset
        real(dp), allocatable :: values(:)
        integer(i4) :: g, layers
        call occ%get_real('EPAIS', epais, st)
        if (st%failed()) return
        if (epais <= 0.0_dp) then
            call occ%error_at('EPAIS', 'the shell thickness must be > 0 (got ' // &
                              to_text(epais) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call occ%get_real('COEF_RIGI_DRZ', drz, st)
        if (st%failed()) return
        ! the x axis of the plates' user frame (Code_Aster U4.42.01 COQUE ANGL_REP: angles
        ! alpha, beta in degrees of the direction (cos b cos a, cos b sin a, -sin b), as its
        ! coqrep; VECTEUR: the direction itself)
        direction = [1.0_dp, 0.0_dp, 0.0_dp]
        if (occ%has('ANGL_REP')) then
            call occ%get_reals('ANGL_REP', values, st)
            if (st%failed()) return
            values = values * (acos(-1.0_dp) / 180.0_dp)
            direction = [cos(values(2)) * cos(values(1)), cos(values(2)) * sin(values(1)), &
                -sin(values(2))]
        else if (occ%has('VECTEUR')) then
            call occ%get_reals('VECTEUR', values, st)
            if (st%failed()) return
            if (.not. norm2(values) > 0.0_dp) then
                call occ%error_at('VECTEUR', 'the direction of the plates'' frame must ' // &
                    'not be zero', st, code=STATUS_MODEL_ERROR)
                return
            end if
            direction = values / norm2(values)
        end if
        layers = 1
        if (occ%has('COQUE_NCOU')) call occ%get_int('COQUE_NCOU', layers, st)
        if (st%failed()) return
        offset = 0.0_dp
        if (occ%has('EXCENTREMENT')) call occ%get_real('EXCENTREMENT', offset, st)
        if (st%failed()) return
        call read_groups(occ, 'GROUP_MA', mc%mesh, names, groups, st)
        if (st%failed()) return
        skipped = 0
        do g = 1, size(groups)
            cells = cells_of_group(mc%mesh, groups(g))
            if (.not. verify) then
                skipped = skipped + count(.not. is_plate(mc%model%element(cells)))
                cells = pack(cells, is_plate(mc%model%element(cells)))
            end if
            ! a negative COEF_RIGI_DRZ makes Code_Aster's DKQ another element, with
            ! drilling rotations tied to the membrane (dkqrig's 'dri' branch): not built,
            ! and refused rather than read as a negative fictitious stiffness (ssls108i
            ! gave 6 of 8 lines NOOK so)
            if (drz < 0.0_dp .and. any(mc%model%element(cells) == ELEM_DKQ)) then
                call occ%error_at('COEF_RIGI_DRZ', 'a negative value selects Code_Aster''s ' &
                    // 'DKQ with drilling rotations (the membrane enriched by DRZ, dkqrig), ' &
                    // 'which parasol does not build; group ' // names(g)%s // ' has DKQ ' // &
                    'cells: give a positive coefficient (the fictitious DRZ stiffness)', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end if
            call assign_coque(cc%cara, mc%model, mc%mesh, cells, &
                              epais, st, coef_rigi_drz=drz, group=names(g)%s, &
                              direction=direction, layers=layers, offset=offset)
            call relocate_error(occ, 'GROUP_MA', st)
            if (st%failed()) return
        end do
        if (skipped > 0) call ctx%write_mess('    COQUE: ' // to_text(skipped) // &
            ' cell(s) of its groups carry no plate element: passed over (VERIF=''MAILLE'' ' &
            // 'makes that an error)')
    end subroutine coque_occurrence

    ! DISCRET / DISCRET_2D: CARA, VALE (count checked at VALE), REPERE, SYME on each
    ! group; an occurrence without CARA (the catalog allows it) does nothing. Cells without
    ! a discrete element are passed over unless VERIF (a note in the .mess says how many).
    subroutine discrete_occurrence(ctx, occ, keyword, mc, cc, verify, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: keyword
        type(model_concept_t), intent(in) :: mc
        type(cara_elem_concept_t), intent(inout) :: cc
        logical, intent(in) :: verify
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:)
        character(len=:), allocatable :: cara, repere, syme
        real(dp), allocatable :: vale(:)
        integer(i4) :: g, skipped, total
        if (.not. occ%has('CARA')) return
        call occ%get_text('CARA', cara, st)
        if (st%ok()) call occ%get_text('REPERE', repere, st)
        if (st%ok()) call occ%get_text('SYME', syme, st)
        if (st%ok()) call occ%get_reals('VALE', vale, st)
        if (st%failed()) return
        call read_groups(occ, 'GROUP_MA', mc%mesh, names, groups, st)
        if (st%failed()) return
        total = 0
        do g = 1, size(groups)
            call assign_discrete(cc%cara, mc%model, mc%mesh, &
                cells_of_group(mc%mesh, groups(g)), keyword, cara, vale, repere, st, &
                group=names(g)%s, symmetric=to_upper(syme) == 'OUI', verify=verify, &
                n_skipped=skipped)
            if (index(st%message, 'values in VALE') > 0) then
                call relocate_error(occ, 'VALE', st)
            else
                call relocate_error(occ, 'CARA', st)
            end if
            if (st%failed()) return
            total = total + skipped
        end do
        if (total > 0) call ctx%write_mess('    ' // keyword // ' ' // to_upper(cara) // &
            ': ' // to_text(total) // ' cell(s) of its groups carry no discrete element: ' &
            // 'passed over (VERIF=''MAILLE'' makes that an error)')
    end subroutine discrete_occurrence

    ! MASSIF: the material frame (ANGL_REP, ANGL_EULER, or ANGL_AXE with ORIG_AXE) of the
    ! plane solid cells of GROUP_MA or of the model (TOUT), kept as data (model_cara_elem);
    ! other cells passed over, said in the .mess. CHAM_ORIE (a field of frames) is not built.
    subroutine massif_occurrence(ctx, occ, mc, cc, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(cara_elem_concept_t), intent(inout) :: cc
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:)
        real(dp), allocatable :: angles(:), origin(:)
        integer(i4) :: kind, skipped, k
        if (occ%has('CHAM_ORIE')) then
            call occ%error_at('CHAM_ORIE', 'a field of material frames is not built in ' // &
                'parasol: give ANGL_REP, ANGL_EULER or ORIG_AXE / ANGL_AXE', st, &
                code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (occ%has('TOUT')) then
            cells = [(k, k = 1, mc%mesh%n_cells)]
        else
            call group_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
        end if
        if (occ%has('ANGL_REP')) then
            kind = MASSIF_ANGL_REP
            call occ%get_reals('ANGL_REP', angles, st)
        else if (occ%has('ANGL_EULER')) then
            kind = MASSIF_ANGL_EULER
            call occ%get_reals('ANGL_EULER', angles, st)
        else
            kind = MASSIF_AXE
            allocate (angles(2), source=0.0_dp)
            if (occ%has('ANGL_AXE')) call occ%get_reals('ANGL_AXE', angles, st)
            if (st%ok()) call occ%get_reals('ORIG_AXE', origin, st)
            if (st%ok()) angles = [angles, origin]
        end if
        if (st%failed()) return
        if (kind /= MASSIF_AXE) angles = [angles, spread(0.0_dp, 1, 3 - size(angles))]
        call assign_massif(cc%cara, mc%model, cells, kind, angles, skipped)
        if (skipped > 0 .and. .not. occ%has('TOUT')) call ctx%write_mess('    MASSIF: ' // &
            to_text(skipped) // ' cell(s) of its groups carry no plane solid element: ' // &
            'passed over')
    end subroutine massif_occurrence

    ! ORIENTATION: CARA and VALE (count checked at VALE) on the discrete cells of each group.
    subroutine orientation_occurrence(occ, mc, cc, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(cara_elem_concept_t), intent(inout) :: cc
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:)
        character(len=:), allocatable :: cara
        real(dp), allocatable :: vale(:)
        integer(i4) :: g, n
        call occ%get_text('CARA', cara, st)
        if (st%ok()) call occ%get_reals('VALE', vale, st)
        if (st%failed()) return
        n = merge(1, 3, to_upper(cara) == 'ANGL_VRIL')
        if (size(vale) /= n) then
            call occ%error_at('VALE', cara // ' needs ' // to_text(n) // ' values, got ' // &
                to_text(size(vale, kind=i4)), st, code=STATUS_MODEL_ERROR)
            return
        end if
        call read_groups(occ, 'GROUP_MA', mc%mesh, names, groups, st)
        if (st%failed()) return
        do g = 1, size(groups)
            call assign_orientation(cc%cara, mc%model, mc%mesh, &
                cells_of_group(mc%mesh, groups(g)), cara, vale, st, group=names(g)%s)
            call relocate_error(occ, 'GROUP_MA', st)
            if (st%failed()) return
        end do
    end subroutine orientation_occurrence

    ! One RIGI_PARASOL occurrence: raft cells and coefficients, springs, table, stored
    ! in cc%cara as discrete values.
    subroutine parasol_occurrence(occ, mc, table, cc, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(rigi_parasol_table_t), intent(out) :: table
        type(cara_elem_concept_t), intent(inout) :: cc
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:), springs(:)
        integer(i4), allocatable :: groups(:), raft(:), spring_cells(:)
        real(dp), allocatable :: coefficients(:), vale(:)
        character(len=:), allocatable :: spring_key, cara, label, repere
        integer(i4) :: g
        spring_key = 'GROUP_MA_POI1'
        if (occ%has('GROUP_MA_SEG2')) spring_key = 'GROUP_MA_SEG2'
        call parasol_cara_check(occ, spring_key, cara, st)
        if (st%failed()) return
        call read_groups(occ, 'GROUP_MA', mc%mesh, names, groups, st)
        if (st%failed()) return
        call group_cells(occ, spring_key, mc%mesh, spring_cells, st)
        if (st%ok()) call occ%get_texts(spring_key, springs, st)
        if (st%ok()) call occ%get_reals('VALE', vale, st)
        if (st%failed()) return
        call raft_coefficients(occ, mc%mesh, names, groups, raft, coefficients, st)
        if (st%failed()) return
        label = springs(1)%s
        do g = 2, size(springs)
            label = label // ', ' // springs(g)%s
        end do
        call compute_rigi_parasol(mc%model, mc%mesh, raft, coefficients, spring_cells, cara, &
                                  vale, table, st, spring_group=label)
        call relocate_error(occ, spring_key, st)
        if (st%ok()) call occ%get_text('REPERE', repere, st)
        if (st%ok()) call apply_rigi_parasol(cc%cara, table, cara, repere, st)
        call relocate_error(occ, 'REPERE', st)
    end subroutine parasol_occurrence

    ! CARA of RIGI_PARASOL: one of K_T_D_L (SEG2 springs) / K_T_D_N (POI1 springs).
    subroutine parasol_cara_check(occ, spring_key, cara, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: spring_key
        character(len=:), allocatable, intent(out) :: cara
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: caras(:)
        integer(i4) :: code
        call occ%get_texts('CARA', caras, st)
        if (st%failed()) return
        cara = to_upper(caras(1)%s)
        code = parse_cara(cara)
        if (size(caras) > 1 .or. (code /= CARA_K_T_D_L .and. code /= CARA_K_T_D_N)) then
            call occ%error_at('CARA', 'parasol has translational springs only: give one ' // &
                'CARA, K_T_D_L (GROUP_MA_SEG2) or K_T_D_N (GROUP_MA_POI1); rotational ' // &
                'K_TR_* needs DIS_TR', st, code=STATUS_NOT_IMPLEMENTED)
        else if (code == CARA_K_T_D_L .neqv. spring_key == 'GROUP_MA_SEG2') then
            call occ%error_at('CARA', cara // ' does not fit ' // spring_key // &
                trim(merge(': SEG2 springs take K_T_D_L', ': POI1 springs take K_T_D_N', &
                           spring_key == 'GROUP_MA_SEG2')), st, code=STATUS_MODEL_ERROR)
        end if
    end subroutine parasol_cara_check

    ! Raft cells of the GROUP_MA groups with their COEF_GROUP, or FONC_GROUP at the
    ! distance of each cell centre from the centre point.
    subroutine raft_coefficients(occ, mesh, names, groups, raft, coefficients, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(string_t), intent(in) :: names(:)
        integer(i4), intent(in) :: groups(:)
        integer(i4), allocatable, intent(out) :: raft(:)
        real(dp), allocatable, intent(out) :: coefficients(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: coef(:)
        real(dp) :: centre(3)
        logical :: has_centre
        ! With COEF_GROUP the centre is not used (translational springs only: it would
        ! only matter for the moments of K_TR_*), so it is not looked up: Code_Aster decks
        ! give GROUP_NO_CENTRE out of habit (SSNL130 model B names one its mesh lacks).
        if (occ%has('COEF_GROUP')) then
            call occ%get_reals('COEF_GROUP', coef, st)
            if (st%failed()) return
            call raft_from_groups(mesh, names, coef, raft, coefficients, st)
            call relocate_error(occ, 'COEF_GROUP', st)
            return
        end if
        call centre_point(occ, mesh, centre, has_centre, st)
        if (st%failed()) return
        if (.not. has_centre) then
            call occ%error_at('FONC_GROUP', 'FONC_GROUP is a function of the distance ' // &
                'from a centre: give GROUP_NO_CENTRE, NOEUD_CENTRE or COOR_CENTRE', st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        call function_coefficients(occ, mesh, groups, centre, raft, coefficients, st)
    end subroutine raft_coefficients

    ! The centre point, if one of GROUP_NO_CENTRE, NOEUD_CENTRE, COOR_CENTRE is given.
    subroutine centre_point(occ, mesh, centre, has_centre, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(out) :: centre(3)
        logical, intent(out) :: has_centre
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name
        real(dp), allocatable :: xyz(:)
        centre = 0.0_dp
        has_centre = .true.
        if (occ%has('GROUP_NO_CENTRE')) then
            call occ%get_text('GROUP_NO_CENTRE', name, st)
            if (st%ok()) call parasol_centre(mesh, centre, st, group=name)
            call relocate_error(occ, 'GROUP_NO_CENTRE', st)
        else if (occ%has('NOEUD_CENTRE')) then
            call occ%get_text('NOEUD_CENTRE', name, st)
            if (st%ok()) call parasol_centre(mesh, centre, st, node=name)
            call relocate_error(occ, 'NOEUD_CENTRE', st)
        else if (occ%has('COOR_CENTRE')) then
            call occ%get_reals('COOR_CENTRE', xyz, st)
            if (st%ok()) call parasol_centre(mesh, centre, st, coordinates=xyz)
            call relocate_error(occ, 'COOR_CENTRE', st)
        else
            has_centre = .false.
        end if
    end subroutine centre_point

    ! FONC_GROUP: one function for all groups or one per group, evaluated per raft cell.
    subroutine function_coefficients(occ, mesh, groups, centre, raft, coefficients, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: groups(:)
        real(dp), intent(in) :: centre(3)
        integer(i4), allocatable, intent(out) :: raft(:)
        real(dp), allocatable, intent(out) :: coefficients(:)
        type(status_t), intent(out) :: st
        type(concept_ref_t), allocatable :: refs(:)
        integer(i4), allocatable :: members(:)
        real(dp), allocatable :: values(:)
        integer(i4) :: g, n
        call occ%get_concepts('FONC_GROUP', refs, st)
        if (st%failed()) return
        if (size(refs) /= 1 .and. size(refs) /= size(groups)) then
            call occ%error_at('FONC_GROUP', 'FONC_GROUP needs 1 function or one per group (' &
                // to_text(size(groups, kind=i4)) // '), got ' // &
                to_text(size(refs, kind=i4)), st, code=STATUS_MODEL_ERROR)
            return
        end if
        n = 0
        do g = 1, size(groups)
            n = n + size(cells_of_group(mesh, groups(g)), kind=i4)
        end do
        allocate (raft(n), coefficients(n))
        n = 0
        do g = 1, size(groups)
            members = cells_of_group(mesh, groups(g))
            select type (f => refs(min(g, size(refs, kind=i4)))%ptr)
            class is (function_concept_t)
                call distance_function_values(f, &
                    cell_centre_distances(mesh, members, centre), values, st)
            class default
                call set_error(st, STATUS_MODEL_ERROR, 'expected a function, got ' // &
                               f%type_name())
            end select
            call relocate_error(occ, 'FONC_GROUP', st)
            if (st%failed()) return
            raft(n + 1:n + size(members)) = members
            coefficients(n + 1:n + size(members)) = values
            n = n + size(members, kind=i4)
        end do
    end subroutine function_coefficients

    ! .mess: one line per occurrence; INFO=2 adds the table.
    subroutine write_parasol(ctx, mesh, table, info)
        type(run_context_t), intent(inout) :: ctx
        type(mesh_t), intent(in) :: mesh
        type(rigi_parasol_table_t), intent(in) :: table
        integer(i4), intent(in) :: info
        character(len=120), allocatable :: lines(:)
        integer(i4) :: k
        call ctx%write_mess('    RIGI_PARASOL ' // to_text(table%n) // ' springs')
        if (info < 2) return
        lines = rigi_parasol_lines(mesh, table)
        do k = 1, size(lines)
            call ctx%write_mess(trim(lines(k)))
        end do
    end subroutine write_parasol

end module cara_elem_commands
