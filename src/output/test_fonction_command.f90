!> TEST_FONCTION (U4.92.02): values and attributes of functions, as Code_Aster's
!> test_fonction_ops:
!>  VALEUR    the function at VALE_PARA (a FORMULE: its parameters named by NOM_PARA, in
!>            any order, default its own; a function by points evaluated as Code_Aster's
!>            Python t_fonction, function_algebra.function_value_at), or its mean over
!>            INTERVALLE (a function by points: the difference of its CALC_FONCTION
!>            INTEGRE primitive, with the function's prolongations, at both ends, divided
!>            by the length), against VALE_CALC and VALE_REFE with TEST_RESU's checks
!>            (test_resu_checks) except that a zero VALE_CALC is tested, not skipped (Code_
!>            Aster's test_fonction_ops has no skip; ORDRE_GRANDEUR has no effect there);
!>  ATTRIBUT  NOM_PARA, NOM_RESU, PROL_GAUCHE, PROL_DROITE or INTERPOL of a function
!>            against ATTR_REFE (texts equal or not).
!> The block of a value:
!>  ` ---- FONCTION         INST` / `      F                1.0` then the check lines.
module test_fonction_command
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_NOT_IMPLEMENTED
    use python_format, only: float_repr
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use function_concept, only: function_concept_t, param_binding_t
    use formula_function, only: formula_function_t
    use function_points, only: function_samples_t, samples_of_function, prolongation_name, &
        DEFAULT_RESULT_NAME
    use function_algebra, only: function_value_at, samples_value, samples_trapezes, &
        check_magnitudes
    use table_keywords, only: relocate_at
    use test_resu_format, only: test_check_t, test_resu_header_line
    use test_resu_checks, only: read_checks, write_test_block, test_columns_t, add_column, &
        listing_safe_text, compact_text
    use test_table_command, only: text_check_line
    implicit none
    private

    public :: run_test_fonction, function_value

contains

    !> Handler of TEST_FONCTION.
    subroutine run_test_fonction(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer :: k
        if (allocated(result)) deallocate (result)
        do k = 1, cmd%count('VALEUR')
            call test_value(ctx, cmd%occurrence('VALEUR', k), st)
            if (st%failed()) return
        end do
        do k = 1, cmd%count('ATTRIBUT')
            call test_attribute(ctx, cmd%occurrence('ATTRIBUT', k), st)
            if (st%failed()) return
        end do
    end subroutine run_test_fonction

    !> One VALEUR occurrence.
    subroutine test_value(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: f
        type(test_check_t), allocatable :: checks(:)
        type(test_columns_t) :: cols
        type(string_t), allocatable :: names(:)
        real(dp), allocatable :: values(:)
        real(dp) :: computed
        character(len=:), allocatable :: last_name
        logical :: integers
        call occ%get_concept('FONCTION', f, st)
        if (st%failed()) return
        call read_checks(occ, checks, integers, st)
        if (st%failed()) return
        checks(1)%skip = .false.              ! Code_Aster's test_fonction_ops never skips
        checks(1)%magnitude = 1.0_dp
        allocate (names(0))
        if (occ%has('NOM_PARA')) call occ%get_texts('NOM_PARA', names, st)
        if (st%failed()) return
        if (occ%has('INTERVALLE')) then
            call occ%get_reals('INTERVALLE', values, st)
            if (st%ok()) call mean_over_interval(occ, f, values(1), values(2), computed, st)
            if (st%failed()) return
            values = values(1:1)
        else
            call occ%get_reals('VALE_PARA', values, st)
            if (st%ok()) call function_value(occ, f, names, values, computed, st)
            if (st%failed()) return
        end if
        last_name = parameter_name(f, names)
        call add_column(cols, 'FONCTION', concept_display_name(f))
        call add_column(cols, last_name, float_repr(values(size(values))))
        call write_test_block(ctx, cols, checks, computed, 'TEST_FONCTION')
    end subroutine test_value

    !> The name printed for the tested parameter: NOM_PARA's last, else the function's.
    function parameter_name(f, names) result(name)
        class(concept_t), intent(in) :: f
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: name
        type(string_t), allocatable :: own(:)
        name = 'TOUTPARA'
        if (size(names) > 0) then
            name = names(size(names))%s
            return
        end if
        select type (f)
        class is (function_concept_t)
            own = f%parameters()
            if (size(own) > 0) name = own(size(own))%s
        end select
    end function parameter_name

    !> The value of a function at `values` named `names` (a FORMULE: bound by name; a
    !> tabulated function or a constant: its parameter is the first value, whatever its
    !> name, as Code_Aster's lafonc(valpu[0])).
    !>  st : located at VALE_PARA or NOM_PARA
    subroutine function_value(occ, f, names, values, y, st)
        type(keyword_set_t), intent(in) :: occ
        class(concept_t), intent(in) :: f
        type(string_t), intent(in) :: names(:)
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(inout) :: st
        type(param_binding_t) :: binding
        type(string_t), allocatable :: own(:)
        character(len=64), allocatable :: given(:)
        integer :: k, j
        y = 0.0_dp
        select type (f)
        type is (formula_function_t)
            own = f%parameters()
            allocate (given(size(values)))
            if (size(names) == 0) then
                do k = 1, min(size(values), size(own))
                    given(k) = own(k)%s
                end do
            else
                if (size(names) /= size(values)) then
                    call occ%error_at('VALE_PARA', to_text(int(size(values), i4)) // &
                        ' values for ' // to_text(int(size(names), i4)) // ' NOM_PARA', st)
                    return
                end if
                do k = 1, size(names)
                    given(k) = names(k)%s
                end do
            end if
            do j = 1, size(own)
                if (.not. any(given == own(j)%s)) then
                    call occ%error_at('NOM_PARA', 'formula ' // concept_display_name(f) // &
                        ' takes ' // own(j)%s // ': name its parameters in NOM_PARA ' // &
                        '(it has ' // joined(own) // ')', st)
                    return
                end if
            end do
            call f%bind(given, binding)
            call f%evaluate(binding, values, y, st)
        class is (function_concept_t)
            if (size(values) > 0) call function_value_at(f, values(1), y, st)
        class default
            call occ%error_at('FONCTION', 'not a function', st)
            return
        end select
        if (st%failed()) call relocate_at(occ, 'VALE_PARA', st)
    end subroutine function_value

    function joined(words) result(text)
        type(string_t), intent(in) :: words(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(words)
            if (k > 1) text = text // ', '
            text = text // words(k)%s
        end do
    end function joined

    !> INTERVALLE: (G(b) - G(a)) / (b - a), G the primitive of the function by trapezes
    !> (CALC_FONCTION INTEGRE, 0 at the first abscissa) with the function's prolongations,
    !> evaluated as Code_Aster's test_fonction_ops does.
    subroutine mean_over_interval(occ, f, a, b, mean, st)
        type(keyword_set_t), intent(in) :: occ
        class(concept_t), intent(in) :: f
        real(dp), intent(in) :: a, b
        real(dp), intent(out) :: mean
        type(status_t), intent(inout) :: st
        type(function_samples_t) :: s, primitive
        real(dp) :: ga, gb
        mean = 0.0_dp
        call samples_of_function(f, s, st)
        if (st%ok()) call check_magnitudes(s, st)
        if (st%ok()) call samples_trapezes(s, 0.0_dp, primitive, st)
        if (st%failed()) then
            call relocate_at(occ, 'FONCTION', st)
            return
        end if
        if (.not. b > a) then
            call occ%error_at('INTERVALLE', 'give an interval (a, b) with a < b', st)
            return
        end if
        primitive%left = s%left
        primitive%right = s%right
        call samples_value(primitive, a, ga, st)
        if (st%ok()) call samples_value(primitive, b, gb, st)
        if (st%failed()) then
            call relocate_at(occ, 'INTERVALLE', st)
            return
        end if
        mean = (gb - ga) / (b - a)
    end subroutine mean_over_interval

    !> One ATTRIBUT occurrence.
    subroutine test_attribute(ctx, occ, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: f
        type(function_samples_t) :: s
        type(string_t) :: expected(1)
        type(string_t) :: lines(4)
        character(len=:), allocatable :: attribute, value, kind, id
        integer :: k
        call occ%get_concept('FONCTION', f, st)
        if (st%ok()) call occ%get_text('ATTR', attribute, st)
        if (st%ok()) call occ%get_text('ATTR_REFE', expected(1)%s, st)
        if (st%failed()) return
        select type (f)
        type is (formula_function_t)
            s%parameter = joined(f%parameters())
            s%result_name = DEFAULT_RESULT_NAME
        class default
            call samples_of_function(f, s, st)
            if (st%failed()) then
                call relocate_at(occ, 'FONCTION', st)
                return
            end if
        end select
        select case (attribute)
        case ('NOM_PARA')
            value = s%parameter
        case ('NOM_RESU')
            value = s%result_name
        case ('PROL_GAUCHE')
            value = prolongation_name(s%left)
        case ('PROL_DROITE')
            value = prolongation_name(s%right)
        case ('INTERPOL')
            value = 'LIN LIN'
        case default
            call occ%error_at('ATTR', attribute // ' is an attribute of a NAPPE (a function ' // &
                'of two parameters), which parasol does not build', st, STATUS_NOT_IMPLEMENTED)
            return
        end select
        kind = 'NON_REGRESSION'
        if (occ%has('REFERENCE')) call occ%get_text('REFERENCE', kind, st)
        if (st%failed()) return
        lines(1)%s = ' ---- FONCTION         ATTR'
        lines(2)%s = '      ' // pad(concept_display_name(f), 17) // attribute
        lines(3)%s = test_resu_header_line()
        lines(4)%s = text_check_line(kind, '', expected, value)
        do k = 1, 4
            call ctx%write_resu(listing_safe_text(lines(k)%s))
        end do
        call ctx%count_test(lines(4)%s(1:4) == ' OK ')
        id = compact_text(lines(2)%s)
        call ctx%write_mess('    TEST_FONCTION ' // id // ': ' // &
                            listing_safe_text(compact_text(lines(4)%s)))
    end subroutine test_attribute

    pure function pad(text, width) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function pad

end module test_fonction_command
