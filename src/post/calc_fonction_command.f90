!> CALC_FONCTION (U4.32.04), the operations parasol builds on real functions given by
!> points (DEFI_FONCTION, DEFI_CONSTANTE, RECU_FONCTION, CALC_FONCTION), as Code_Aster's
!> calc_fonction_ops does them with t_fonction (function_algebra):
!>  - COMB: sum of COEF * FONCTION over the occurrences, on the union of the abscissae;
!>    MULT: product of the functions. Both take the names and prolongations of the first
!>    function, then LIST_PARA (when given) resamples the result at its values;
!>  - DERIVE (DIFF_CENTREE), INTEGRE (TRAPEZE or SIMPSON, from COEF at the first abscissa);
!>  - ABS, INVERSE, ENVELOPPE (SUP / INF), PUISSANCE (EXPOSANT, an integer >= 1).
!> The result is then made as Code_Aster's DEFI_FONCTION makes it: NOM_PARA, NOM_RESU,
!> INTERPOL, PROL_GAUCHE, PROL_DROITE given to the command override the computed ones;
!> abscissae must increase strictly. Sheets of functions (nappes), complex functions and
!> the seismic operations (SPEC_OSCI, FFT, ...) are not built; the catalog does not offer
!> them, so a deck using them stops at validation.
module calc_fonction_command
    use kinds, only: dp
    use strings, only: real_e13
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use run_context, only: run_context_t
    use tabulated_function, only: tabulated_function_t
    use real_list, only: real_list_t
    use function_points, only: function_samples_t, samples_of_function
    use function_algebra, only: samples_at, samples_sum, samples_product, samples_scaled, &
        samples_derivative, samples_trapezes, samples_simpson, samples_inverse, &
        samples_abs, samples_envelope, check_magnitudes
    use table_keywords, only: relocate_at
    use recu_fonction_command, only: set_function_attributes
    implicit none
    private

    public :: run_calc_fonction

    !> The operations, one of which the catalog's UN_PARMI rule lets through.
    character(len=9), parameter :: OPERATIONS(8) = [character(len=9) :: 'COMB', 'MULT', &
        'DERIVE', 'INTEGRE', 'ABS', 'INVERSE', 'ENVELOPPE', 'PUISSANCE']

    !> The largest EXPOSANT: a power is a repeated product of samples.
    integer, parameter :: MAX_EXPONENT = 1000

contains

    !> Handler of CALC_FONCTION.
    subroutine run_calc_fonction(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(function_samples_t) :: g
        type(tabulated_function_t), allocatable :: f
        character(len=:), allocatable :: operation
        integer :: k, info
        operation = ''
        info = 1
        do k = 1, size(OPERATIONS)
            if (cmd%count(trim(OPERATIONS(k))) > 0) operation = trim(OPERATIONS(k))
        end do
        select case (operation)
        case ('COMB', 'MULT')
            call combination(cmd, operation, g, st)
            if (st%ok() .and. cmd%has('LIST_PARA')) call resample(cmd, g, st)
        case ('DERIVE', 'INTEGRE', 'ABS', 'INVERSE', 'PUISSANCE')
            call unary(cmd%occurrence(operation, 1), operation, g, st)
        case ('ENVELOPPE')
            call envelope(cmd%occurrence(operation, 1), g, st)
        case default
            call cmd%error_at('FONCTION', 'CALC_FONCTION needs one of COMB, MULT, DERIVE, ' // &
                'INTEGRE, ABS, INVERSE, ENVELOPPE, PUISSANCE', st, STATUS_NOT_IMPLEMENTED)
        end select
        if (st%failed()) return
        allocate (f)
        f%x = g%x
        f%y = g%y
        f%parameter = g%parameter
        f%result_name = g%result_name
        f%left = g%left
        f%right = g%right
        call set_function_attributes(cmd, f, st)
        if (st%failed()) return
        do k = 2, size(f%x)
            if (.not. f%x(k) > f%x(k - 1)) then
                call cmd%error_at(operation, 'the abscissae of the result do not increase ' // &
                    '(' // real_e13(f%x(k - 1)) // ' then ' // real_e13(f%x(k)) // '): it is ' // &
                    'not a function DEFI_FONCTION would make', st, STATUS_MODEL_ERROR)
                return
            end if
        end do
        if (cmd%has('INFO')) call cmd%get_int('INFO', info, st)
        if (st%failed()) return
        if (info > 1) call print_function(ctx, f)
        call move_alloc(f, result)
    end subroutine run_calc_fonction

    !> INFO=2: the points of the result in the .mess (Code_Aster prints them with
    !> IMPR_FONCTION FORMAT='TABLEAU' on the message unit).
    subroutine print_function(ctx, f)
        type(run_context_t), intent(inout) :: ctx
        type(tabulated_function_t), intent(in) :: f
        integer :: k
        call ctx%write_mess('    CALC_FONCTION: ' // f%parameter // ' ' // f%result_name)
        do k = 1, size(f%x)
            call ctx%write_mess('    ' // real_e13(f%x(k)) // ' ' // real_e13(f%y(k)))
        end do
    end subroutine print_function

    !> COMB (sum of COEF * FONCTION) or MULT (product) over the occurrences, with the
    !> names and prolongations of the first function.
    subroutine combination(cmd, operation, g, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: operation
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        type(function_samples_t), allocatable :: fs(:)
        type(function_samples_t) :: term, accumulated
        type(keyword_set_t) :: occ
        real(dp) :: coef
        integer :: k
        do k = 1, cmd%count(operation)
            occ = cmd%occurrence(operation, k)
            call operands(occ, fs, st)
            if (st%failed()) return
            term = fs(1)
            if (operation == 'COMB') then
                call occ%get_real('COEF', coef, st)
                if (st%ok()) call samples_scaled(fs(1), coef, term, st)
            end if
            if (st%ok() .and. k > 1) then
                if (operation == 'COMB') then
                    call samples_sum(term, accumulated, g, st)
                else
                    call samples_product(term, accumulated, g, st)
                end if
            else if (st%ok()) then
                g = term
            end if
            if (st%failed()) then
                call relocate_at(occ, 'FONCTION', st)
                return
            end if
            accumulated = g
        end do
        call operands(cmd%occurrence(operation, 1), fs, st)
        if (st%failed()) return
        g%parameter = fs(1)%parameter
        g%result_name = fs(1)%result_name
        g%left = fs(1)%left
        g%right = fs(1)%right
    end subroutine combination

    !> LIST_PARA: the result at those abscissae (Code_Aster's evalfonc).
    subroutine resample(cmd, g, st)
        type(command_t), intent(in) :: cmd
        type(function_samples_t), intent(inout) :: g
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: c
        type(function_samples_t) :: at
        call cmd%get_concept('LIST_PARA', c, st)
        if (st%failed()) return
        select type (c)
        type is (real_list_t)
            at%x = c%values
            at%y = c%values
            call check_magnitudes(at, st)
            if (st%ok()) call samples_at(g, c%values, at, st)
            if (st%ok()) g = at
        class default
            call cmd%error_at('LIST_PARA', concept_display_name(c) // ' is not a list of ' // &
                'reals (DEFI_LIST_REEL)', st)
        end select
        if (st%failed()) call relocate_at(cmd, 'LIST_PARA', st)
    end subroutine resample

    !> DERIVE, INTEGRE, ABS, INVERSE, PUISSANCE of the one function of `occ`.
    subroutine unary(occ, operation, g, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: operation
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        type(function_samples_t), allocatable :: fs(:)
        type(function_samples_t) :: power
        character(len=:), allocatable :: method
        real(dp) :: coef
        integer :: exponent_value, k
        call operands(occ, fs, st)
        if (st%failed()) return
        select case (operation)
        case ('DERIVE')
            call samples_derivative(fs(1), g, st)
        case ('INTEGRE')
            call occ%get_text('METHODE', method, st)
            if (st%ok()) call occ%get_real('COEF', coef, st)
            if (st%failed()) return
            if (method == 'SIMPSON') then
                call samples_simpson(fs(1), coef, g, st)
            else
                call samples_trapezes(fs(1), coef, g, st)
            end if
        case ('ABS')
            call samples_abs(fs(1), g)
        case ('INVERSE')
            call samples_inverse(fs(1), g)
            do k = 2, size(g%x)
                if (.not. g%x(k) > g%x(k - 1)) then
                    call occ%error_at('FONCTION', 'the ordinates of ' // &
                        function_name(occ) // ' are not strictly monotonic: the function ' // &
                        'has no inverse', st, STATUS_MODEL_ERROR)
                    return
                end if
            end do
        case ('PUISSANCE')
            call occ%get_int('EXPOSANT', exponent_value, st)
            if (st%failed()) return
            if (exponent_value < 1 .or. exponent_value > MAX_EXPONENT) then
                call occ%error_at('EXPOSANT', 'EXPOSANT is a power from 1 to 1000 (the ' // &
                    'function times itself)', st)
                return
            end if
            g = fs(1)
            do k = 2, exponent_value
                call samples_product(g, fs(1), power, st)
                if (st%failed()) exit
                g = power
            end do
        end select
        if (st%failed()) call relocate_at(occ, 'FONCTION', st)
    end subroutine unary

    !> ENVELOPPE of the functions of the occurrence, SUP or INF.
    subroutine envelope(occ, g, st)
        type(keyword_set_t), intent(in) :: occ
        type(function_samples_t), intent(out) :: g
        type(status_t), intent(inout) :: st
        type(function_samples_t), allocatable :: fs(:)
        character(len=:), allocatable :: criterion
        call operands(occ, fs, st)
        if (st%ok()) call occ%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        call samples_envelope(fs, criterion == 'SUP', g, st)
        if (st%failed()) call relocate_at(occ, 'FONCTION', st)
    end subroutine envelope

    !> The points of the functions at FONCTION of `occ`, checked to be within the
    !> operations' range.
    subroutine operands(occ, fs, st)
        type(keyword_set_t), intent(in) :: occ
        type(function_samples_t), allocatable, intent(out) :: fs(:)
        type(status_t), intent(inout) :: st
        type(concept_ref_t), allocatable :: refs(:)
        integer :: k
        call occ%get_concepts('FONCTION', refs, st)
        if (st%failed()) return
        allocate (fs(size(refs)))
        do k = 1, size(refs)
            call samples_of_function(refs(k)%ptr, fs(k), st)
            if (st%ok()) call check_magnitudes(fs(k), st)
            if (st%failed()) then
                call relocate_at(occ, 'FONCTION', st)
                return
            end if
        end do
    end subroutine operands

    !> The name of the (first) function at FONCTION of `occ`, for messages.
    function function_name(occ) result(name)
        type(keyword_set_t), intent(in) :: occ
        character(len=:), allocatable :: name
        type(concept_ref_t), allocatable :: refs(:)
        type(status_t) :: st
        name = 'the function'
        call occ%get_concepts('FONCTION', refs, st)
        if (st%ok() .and. size(refs) > 0) name = concept_display_name(refs(1)%ptr)
    end function function_name

end module calc_fonction_command
