!> The stored instants a post-processing command asks for (CREA_TABLE RESU, POST_RELEVE_T,
!> RECU_FONCTION): TOUT_ORDRE (or nothing: every stored instant), NUME_ORDRE, INST or
!> LIST_INST, an instant being found within PRECISION (CRITERE 'RELATIF': relative to the
!> instant asked for, 'ABSOLU'), as Code_Aster's rsorac. Each asked value must be stored:
!> the error names it and lists what is.
module result_instants
    use kinds, only: dp, i4
    use strings, only: to_text, real_e13
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t
    use deck_command, only: keyword_set_t
    use real_list, only: real_list_t
    use result_fields, only: result_fields_t
    implicit none
    private

    !> Stored instants listed in an error message, at most.
    integer, parameter :: LISTED = 10

    public :: selected_instants, instant_matches

contains

    !> The indices (1..res%n_stored) of the instants `occ` asks for, in the order asked.
    !>  by_inst : out, true when they were asked by INST or LIST_INST (the tables then
    !>            have an INST column, as Code_Aster's)
    !>  st : located at NUME_ORDRE / INST / LIST_INST for a value not stored
    subroutine selected_instants(occ, res, indices, by_inst, st)
        class(keyword_set_t), intent(in) :: occ
        class(result_fields_t), intent(in) :: res
        integer, allocatable, intent(out) :: indices(:)
        logical, intent(out) :: by_inst
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: numbers(:)
        real(dp), allocatable :: instants(:)
        character(len=:), allocatable :: criterion, key
        class(concept_t), pointer :: list
        real(dp) :: precision
        integer :: k, j, found
        by_inst = .false.
        allocate (indices(0))
        if (occ%has('NUME_ORDRE')) then
            call occ%get_ints('NUME_ORDRE', numbers, st)
            if (st%failed()) return
            deallocate (indices)
            allocate (indices(size(numbers)))
            do k = 1, size(numbers)
                found = findloc(res%nume_ordre(1:res%n_stored), numbers(k), dim=1)
                if (found == 0) then
                    call occ%error_at('NUME_ORDRE', 'NUME_ORDRE ' // to_text(numbers(k)) // &
                        ' is not stored in ' // res%name // ' (stored: ' // &
                        stored_numbers(res) // ')', st, STATUS_MODEL_ERROR)
                    return
                end if
                indices(k) = found
            end do
        else if (occ%has('INST') .or. occ%has('LIST_INST')) then
            by_inst = .true.
            key = 'INST'
            if (occ%has('INST')) then
                call occ%get_reals('INST', instants, st)
            else
                key = 'LIST_INST'
                call occ%get_concept('LIST_INST', list, st)
                if (st%ok()) then
                    select type (list)
                    type is (real_list_t)
                        instants = list%values
                    class default
                        call occ%error_at('LIST_INST', 'expected a list of reals ' // &
                            '(DEFI_LIST_REEL)', st)
                    end select
                end if
            end if
            if (st%failed()) return
            criterion = 'RELATIF'
            precision = 1.0e-6_dp
            if (occ%has('CRITERE')) call occ%get_text('CRITERE', criterion, st)
            if (st%ok() .and. occ%has('PRECISION')) call occ%get_real('PRECISION', precision, st)
            if (st%failed()) return
            deallocate (indices)
            allocate (indices(size(instants)))
            do k = 1, size(instants)
                found = 0
                do j = 1, res%n_stored
                    if (instant_matches(res%inst(j), instants(k), criterion, precision)) then
                        found = j
                        exit
                    end if
                end do
                if (found == 0) then
                    call occ%error_at(key, 'INST ' // real_e13(instants(k)) // ' is not ' // &
                        'stored in ' // res%name // ' within PRECISION ' // &
                        real_e13(precision) // ' (' // criterion // '; stored: ' // &
                        stored_instants(res) // ')', st, STATUS_MODEL_ERROR)
                    return
                end if
                indices(k) = found
            end do
        else
            deallocate (indices)
            indices = [(k, k=1, res%n_stored)]
        end if
    end subroutine selected_instants

    !> True when stored instant `stored` is `asked` within `precision` (RELATIF: relative to
    !> |asked|, absolute when asked = 0).
    pure logical function instant_matches(stored, asked, criterion, precision)
        real(dp), intent(in) :: stored, asked, precision
        character(len=*), intent(in) :: criterion
        if (criterion == 'ABSOLU' .or. .not. abs(asked) > 0.0_dp) then
            instant_matches = abs(stored - asked) <= precision
        else
            instant_matches = abs(stored - asked) <= precision * abs(asked)
        end if
    end function instant_matches

    function stored_numbers(res) result(text)
        class(result_fields_t), intent(in) :: res
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, min(res%n_stored, LISTED)
            if (k > 1) text = text // ', '
            text = text // to_text(res%nume_ordre(k))
        end do
        if (res%n_stored > LISTED) text = text // ', ... ' // to_text(res%nume_ordre(res%n_stored))
        if (res%n_stored == 0) text = 'none'
    end function stored_numbers

    function stored_instants(res) result(text)
        class(result_fields_t), intent(in) :: res
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, min(res%n_stored, LISTED)
            if (k > 1) text = text // ', '
            text = text // real_e13(res%inst(k))
        end do
        if (res%n_stored > LISTED) text = text // ', ... ' // real_e13(res%inst(res%n_stored))
        if (res%n_stored == 0) text = 'none'
    end function stored_instants

end module result_instants
