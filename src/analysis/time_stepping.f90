!> DEFI_LIST_INST (Code_Aster U4.34.03): the 'list_inst' concept STAT_NON_LINE takes as
!> INCREMENT/LIST_INST: the instants (DEFI_LIST: VALE, LIST_INST, or the instants of a
!> RESULTAT cut into SUBD_PAS) and what to do when a step fails (ECHEC: one occurrence
!> per event, each with its action).
!>
!> Code_Aster's defaults, which its catalog gives in blocks conditional on the event, the
!> action and the subdivision method (catalog_list_inst explains why they are applied
!> here): no ECHEC is one occurrence EVENEMENT = 'ERREUR', ACTION = 'DECOUPE',
!> SUBD_METHODE = 'MANUEL', SUBD_PAS = 4, SUBD_NIVEAU = 3, SUBD_PAS_MINI = 0. ACTION's
!> default depends on the event: DECOUPE for ERREUR, DELTA_GRANDEUR, DIVE_RESI and
!> RESI_MAXI, ADAPT_COEF_PENA for INTERPENETRATION, CONTINUE for INSTABILITE.
!>
!> What STAT_NON_LINE builds of it (step_cutting_for): the event ERREUR (a step that does
!> not converge: ITER_GLOB_MAXI reached, or no equilibrium found) with ARRET (stop) or
!> DECOUPE by the MANUEL method (the step cut into SUBD_PAS equal steps, at most
!> SUBD_NIVEAU times nested, never below SUBD_PAS_MINI: Code_Aster nmdecm, nmdecv);
!> INSTABILITE has no effect (parasol has no CRIT_STAB). A list that asks for more (METHODE
!> = 'AUTO', SUBD_METHODE = 'AUTO', ITER_SUPPL, the events DELTA_GRANDEUR, RESI_MAXI,
!> DIVE_RESI, INTERPENETRATION) stops the analysis that uses it, naming what is not built.
module time_stepping
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, real_e13
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use real_list, only: real_list_t
    use analysis_result, only: result_concept_t
    use number_limits, only: is_finite
    implicit none
    private

    !> Code_Aster's defaults of the DECOUPE action, MANUEL method (U4.34.03).
    integer(i4), parameter, public :: DEFAULT_SUBD_PAS = 4, DEFAULT_SUBD_NIVEAU = 3
    real(dp), parameter, public :: DEFAULT_SUBD_PAS_MINI = 0.0_dp
    !> ... of ITER_SUPPL and ADAPT_COEF_PENA.
    integer(i4), parameter :: DEFAULT_PCENT_ITER_PLUS = 50
    real(dp), parameter :: DEFAULT_COEF_MAXI = 1.0e12_dp

    !> Most instants DEFI_LIST may make of a RESULTAT's (the list is allocated; issue 13).
    integer(i4), parameter :: MAX_LIST_INSTANTS = 10000000

    !> One ECHEC occurrence.
    type, public :: failure_event_t
        character(len=:), allocatable :: event, action, subd_methode
        integer(i4) :: subd_pas = DEFAULT_SUBD_PAS, subd_niveau = DEFAULT_SUBD_NIVEAU
        real(dp) :: subd_pas_mini = DEFAULT_SUBD_PAS_MINI
        integer(i4) :: pcent_iter_plus = DEFAULT_PCENT_ITER_PLUS
        real(dp) :: coef_maxi = DEFAULT_COEF_MAXI
        character(len=:), allocatable :: where   !< "deck.comm:L:C" of the occurrence
    end type failure_event_t

    !> What a failed step does, as STAT_NON_LINE applies it.
    type, public :: step_cutting_t
        logical :: enabled = .false.              !< DECOUPE (else ARRET: stop)
        integer(i4) :: subd_pas = DEFAULT_SUBD_PAS
        integer(i4) :: subd_niveau = DEFAULT_SUBD_NIVEAU
        real(dp) :: subd_pas_mini = DEFAULT_SUBD_PAS_MINI
    end type step_cutting_t

    !> The list_inst concept.
    type, extends(concept_t), public :: list_inst_concept_t
        real(dp), allocatable :: instants(:)
        character(len=:), allocatable :: method            !< METHODE: MANUEL or AUTO
        type(failure_event_t), allocatable :: events(:)    !< ECHEC occurrences
    contains
        procedure :: type_name => list_inst_type_name
        procedure :: summary => list_inst_summary
    end type list_inst_concept_t

    public :: run_defi_list_inst, step_cutting_for

contains

    function list_inst_type_name(self) result(name)
        class(list_inst_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'list_inst'
        if (.false.) name = self%name
    end function list_inst_type_name

    !> "L (list_inst): 11 instants from 0 to 1, ECHEC ERREUR: DECOUPE".
    function list_inst_summary(self) result(text)
        class(list_inst_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer :: k
        text = concept_display_name(self) // ' (list_inst): ' // &
            to_text(size(self%instants)) // ' instants'
        if (size(self%instants) > 0) text = text // ' from ' // &
            to_text(self%instants(1)) // ' to ' // to_text(self%instants(size(self%instants)))
        text = text // ', METHODE ' // self%method // ', ECHEC'
        do k = 1, size(self%events)
            text = text // ' ' // self%events(k)%event // ': ' // self%events(k)%action
        end do
    end function list_inst_summary

    !> DEFI_LIST_INST.
    !>  result : out, a list_inst_concept_t
    !>  st     : out, located at the keyword: instants not strictly increasing, a RESULTAT
    !>           without instants, an ACTION the EVENEMENT does not take, a keyword of
    !>           another event or action, a mandatory keyword of the event missing, an
    !>           event given twice
    subroutine run_defi_list_inst(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(list_inst_concept_t), allocatable :: li
        type(keyword_set_t) :: occ
        integer(i4) :: k, j
        allocate (li)
        call cmd%get_text('METHODE', li%method, st)
        if (st%failed()) return
        call read_instants(cmd%occurrence('DEFI_LIST', 1), li%instants, st)
        if (st%failed()) return
        if (cmd%count('ECHEC') == 0) then
            allocate (li%events(1))
            li%events(1)%event = 'ERREUR'
            li%events(1)%action = 'DECOUPE'
            li%events(1)%subd_methode = 'MANUEL'
            li%events(1)%where = ''
        else
            allocate (li%events(cmd%count('ECHEC')))
            do k = 1, cmd%count('ECHEC')
                occ = cmd%occurrence('ECHEC', k)
                call read_event(occ, li%events(k), st)
                if (st%failed()) return
                do j = 1, k - 1
                    if (li%events(j)%event /= li%events(k)%event) cycle
                    call occ%error_at('EVENEMENT', 'the event ' // &
                        li%events(k)%event // ' is given twice (also at ' // &
                        li%events(j)%where // '): one ECHEC per event', st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end do
            end do
        end if
        call ctx%write_mess('    ' // li%summary())
        call move_alloc(li, result)
    end subroutine run_defi_list_inst

    ! DEFI_LIST: VALE, LIST_INST, or RESULTAT with SUBD_PAS (each interval of the result's
    ! instants cut into SUBD_PAS equal steps).
    subroutine read_instants(occ, instants, st)
        type(keyword_set_t), intent(in) :: occ
        real(dp), allocatable, intent(out) :: instants(:)
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        character(len=:), allocatable :: key
        integer(i4) :: k, i, n, pas
        real(dp), allocatable :: base(:)
        if (occ%has('VALE')) then
            key = 'VALE'
            call occ%get_reals('VALE', instants, st)
            if (st%failed()) return
        else if (occ%has('LIST_INST')) then
            key = 'LIST_INST'
            call occ%get_concept('LIST_INST', p, st)
            if (st%failed()) return
            select type (p)
            type is (real_list_t)
                instants = p%values
            class default
                call occ%error_at(key, 'expected a list of reals (DEFI_LIST_REEL), got ' // &
                    p%type_name(), st)
                return
            end select
        else
            key = 'RESULTAT'
            call occ%get_concept('RESULTAT', p, st)
            if (st%ok()) call occ%get_int('SUBD_PAS', pas, st)
            if (st%failed()) return
            select type (p)
            type is (result_concept_t)
                base = p%inst(1:p%n_stored)
            class default
                call occ%error_at(key, 'expected a result (evol_elas, evol_noli), got ' // &
                    p%type_name(), st)
                return
            end select
            n = size(base, kind=i4)
            if (n == 0) then
                call occ%error_at(key, 'the result has no instant', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            if (real(n - 1, dp) * real(pas, dp) > real(MAX_LIST_INSTANTS, dp)) then
                call occ%error_at('SUBD_PAS', to_text(n) // ' instants cut into ' // &
                    to_text(pas) // ' make more than ' // to_text(MAX_LIST_INSTANTS) // &
                    ' instants', st, code=STATUS_MODEL_ERROR)
                return
            end if
            allocate (instants((n - 1) * pas + 1))
            instants(1) = base(1)
            do k = 1, n - 1
                do i = 1, pas
                    instants((k - 1) * pas + 1 + i) = base(k) + (base(k + 1) - base(k)) * &
                        real(i, dp) / real(pas, dp)
                end do
            end do
        end if
        if (size(instants) == 0) then
            call occ%error_at(key, 'the list has no instant', st, code=STATUS_MODEL_ERROR)
            return
        end if
        do k = 2, size(instants, kind=i4)
            if (instants(k) > instants(k - 1) .and. is_finite(instants(k) - instants(k - 1))) &
                cycle
            call occ%error_at(key, 'the instants must be strictly increasing: ' // &
                real_e13(instants(k)) // ' follows ' // real_e13(instants(k - 1)) // &
                ' (instant ' // to_text(k) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end do
    end subroutine read_instants

    ! One ECHEC occurrence: Code_Aster's blocks, as rules on the event and the action.
    subroutine read_event(occ, ev, st)
        type(keyword_set_t), intent(in) :: occ
        type(failure_event_t), intent(out) :: ev
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: actions, needs
        character(len=:), allocatable :: file
        integer :: line, col
        call occ%location('', file, line, col)
        ev%where = file // ':' // to_text(line) // ':' // to_text(col)
        call occ%get_text('EVENEMENT', ev%event, st)
        if (st%failed()) return
        select case (ev%event)
        case ('ERREUR')
            actions = 'ARRET DECOUPE ITER_SUPPL'
            ev%action = 'DECOUPE'
            needs = ''
        case ('DELTA_GRANDEUR')
            actions = 'ARRET DECOUPE'
            ev%action = 'DECOUPE'
            needs = 'VALE_REF NOM_CHAM NOM_CMP'
        case ('INTERPENETRATION')
            actions = 'ARRET ADAPT_COEF_PENA'
            ev%action = 'ADAPT_COEF_PENA'
            needs = 'PENE_MAXI'
        case ('DIVE_RESI')
            actions = 'DECOUPE'
            ev%action = 'DECOUPE'
            needs = ''
        case ('RESI_MAXI')
            actions = 'DECOUPE'
            ev%action = 'DECOUPE'
            needs = 'RESI_GLOB_MAXI'
        case default                                    ! INSTABILITE
            actions = 'ARRET CONTINUE'
            ev%action = 'CONTINUE'
            needs = ''
        end select
        if (occ%has('ACTION')) then
            call occ%get_text('ACTION', ev%action, st)
            if (st%failed()) return
            if (index(' ' // actions // ' ', ' ' // ev%action // ' ') == 0) then
                call occ%error_at('ACTION', 'EVENEMENT=''' // ev%event // ''' takes the ' // &
                    'actions ' // actions // ', not ' // ev%action, st)
                return
            end if
        end if
        call check_event_keywords(occ, ev, needs, st)
        if (st%failed()) return
        ev%subd_methode = ''
        if (ev%action == 'DECOUPE' .or. ev%action == 'ITER_SUPPL') then
            ev%subd_methode = 'MANUEL'
            if (occ%has('SUBD_METHODE')) call occ%get_text('SUBD_METHODE', ev%subd_methode, st)
            if (st%ok() .and. occ%has('SUBD_PAS')) call occ%get_int('SUBD_PAS', ev%subd_pas, &
                st)
            if (st%ok() .and. occ%has('SUBD_NIVEAU')) call occ%get_int('SUBD_NIVEAU', &
                ev%subd_niveau, st)
            if (st%ok() .and. occ%has('SUBD_PAS_MINI')) call occ%get_real('SUBD_PAS_MINI', &
                ev%subd_pas_mini, st)
        end if
        if (st%ok() .and. occ%has('PCENT_ITER_PLUS')) call occ%get_int('PCENT_ITER_PLUS', &
            ev%pcent_iter_plus, st)
        if (st%ok() .and. occ%has('COEF_MAXI')) call occ%get_real('COEF_MAXI', ev%coef_maxi, st)
    end subroutine read_event

    ! The keywords of an ECHEC occurrence must belong to its event's and action's blocks
    ! (Code_Aster's b_erreur, b_edelta ..., b_deco, b_supp, b_deco_manu, b_deco_auto,
    ! b_pene), and the event's mandatory ones be there.
    subroutine check_event_keywords(occ, ev, needs, st)
        type(keyword_set_t), intent(in) :: occ
        type(failure_event_t), intent(in) :: ev
        character(len=*), intent(in) :: needs
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: allowed, method
        character(len=*), parameter :: ALL_KEYS(13) = [character(len=15) :: 'SUBD_METHODE', &
            'SUBD_PAS', 'SUBD_NIVEAU', 'SUBD_PAS_MINI', 'PCENT_ITER_PLUS', 'COEF_MAXI', &
            'GROUP_MA', 'GROUP_NO', 'VALE_REF', 'NOM_CHAM', 'NOM_CMP', 'PENE_MAXI', &
            'RESI_GLOB_MAXI']
        integer :: k
        allowed = needs
        if (ev%event == 'DELTA_GRANDEUR') allowed = allowed // ' GROUP_MA GROUP_NO'
        if (ev%action == 'DECOUPE' .or. ev%action == 'ITER_SUPPL') then
            method = 'MANUEL'
            if (occ%has('SUBD_METHODE')) call occ%get_text('SUBD_METHODE', method, st)
            if (st%failed()) return
            allowed = allowed // ' SUBD_METHODE SUBD_PAS_MINI'
            if (method == 'MANUEL') allowed = allowed // ' SUBD_PAS SUBD_NIVEAU'
        end if
        if (ev%action == 'ITER_SUPPL') allowed = allowed // ' PCENT_ITER_PLUS'
        if (ev%action == 'ADAPT_COEF_PENA') allowed = allowed // ' COEF_MAXI'
        do k = 1, size(ALL_KEYS)
            if (.not. occ%has(trim(ALL_KEYS(k)))) cycle
            if (index(' ' // allowed // ' ', ' ' // trim(ALL_KEYS(k)) // ' ') > 0) cycle
            call occ%error_at(trim(ALL_KEYS(k)), trim(ALL_KEYS(k)) // ' does not apply to ' &
                // 'EVENEMENT=''' // ev%event // ''', ACTION=''' // ev%action // '''' // &
                ' (it belongs to ' // owner_of(trim(ALL_KEYS(k))) // ')', st)
            return
        end do
        do k = 1, size(ALL_KEYS)
            if (index(' ' // needs // ' ', ' ' // trim(ALL_KEYS(k)) // ' ') == 0) cycle
            if (occ%has(trim(ALL_KEYS(k)))) cycle
            call occ%error_at('EVENEMENT', 'EVENEMENT=''' // ev%event // ''' needs ' // &
                trim(ALL_KEYS(k)), st)
            return
        end do
    end subroutine check_event_keywords

    ! Where an ECHEC keyword belongs, in words.
    function owner_of(key) result(text)
        character(len=*), intent(in) :: key
        character(len=:), allocatable :: text
        select case (key)
        case ('SUBD_PAS', 'SUBD_NIVEAU')
            text = 'ACTION=''DECOUPE'' or ''ITER_SUPPL'' with SUBD_METHODE=''MANUEL'''
        case ('SUBD_METHODE', 'SUBD_PAS_MINI')
            text = 'ACTION=''DECOUPE'' or ''ITER_SUPPL'''
        case ('PCENT_ITER_PLUS')
            text = 'ACTION=''ITER_SUPPL'''
        case ('COEF_MAXI')
            text = 'ACTION=''ADAPT_COEF_PENA'''
        case ('PENE_MAXI')
            text = 'EVENEMENT=''INTERPENETRATION'''
        case ('RESI_GLOB_MAXI')
            text = 'EVENEMENT=''RESI_MAXI'''
        case default
            text = 'EVENEMENT=''DELTA_GRANDEUR'''
        end select
    end function owner_of

    !> What STAT_NON_LINE does when a step fails, from a list_inst (see the module header).
    !>  list    : in, the concept
    !>  cutting : out, the ERREUR event's policy
    !>  st      : out, STATUS_NOT_IMPLEMENTED naming what parasol does not build (METHODE
    !>            AUTO, SUBD_METHODE AUTO, ITER_SUPPL, the other events), with the ECHEC
    !>            occurrence's location in the message
    subroutine step_cutting_for(list, cutting, st)
        type(list_inst_concept_t), intent(in) :: list
        type(step_cutting_t), intent(out) :: cutting
        type(status_t), intent(out) :: st
        integer :: k
        character(len=:), allocatable :: where
        if (list%method == 'AUTO') then
            call set_error(st, STATUS_NOT_IMPLEMENTED, concept_display_name(list) // &
                ': DEFI_LIST_INST METHODE=''AUTO'' (adaptive time steps) is not built; ' // &
                'give METHODE=''MANUEL'' (the instants of DEFI_LIST)')
            return
        end if
        do k = 1, size(list%events)
            associate (ev => list%events(k))
                where = ''
                if (len(ev%where) > 0) where = ' (ECHEC at ' // ev%where // ')'
                select case (ev%event)
                case ('ERREUR')
                    select case (ev%action)
                    case ('ARRET')
                        cutting%enabled = .false.
                    case ('DECOUPE')
                        if (ev%subd_methode /= 'MANUEL') then
                            call set_error(st, STATUS_NOT_IMPLEMENTED, &
                                concept_display_name(list) // ': SUBD_METHODE=''' // &
                                ev%subd_methode // ''' is not built; use ''MANUEL''' // where)
                            return
                        end if
                        cutting%enabled = .true.
                        cutting%subd_pas = ev%subd_pas
                        cutting%subd_niveau = ev%subd_niveau
                        cutting%subd_pas_mini = ev%subd_pas_mini
                    case default
                        call set_error(st, STATUS_NOT_IMPLEMENTED, concept_display_name(list) &
                            // ': ECHEC ACTION=''' // ev%action // ''' is not built; use ' // &
                            '''DECOUPE'' or ''ARRET''' // where)
                        return
                    end select
                case ('INSTABILITE')
                    continue                  ! no CRIT_STAB in parasol: never detected
                case default
                    call set_error(st, STATUS_NOT_IMPLEMENTED, concept_display_name(list) // &
                        ': ECHEC EVENEMENT=''' // ev%event // ''' is not built (parasol ' // &
                        'acts on ERREUR: a step that does not converge)' // where)
                    return
                end select
            end associate
        end do
    end subroutine step_cutting_for

end module time_stepping
