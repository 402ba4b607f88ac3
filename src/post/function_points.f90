!> The points of a function concept, as Code_Aster stores them (.VALE and .PROL): a
!> DEFI_FONCTION (or a function made by RECU_FONCTION, CALC_FONCTION) holds its abscissae
!> and ordinates; a DEFI_CONSTANTE is one point (1.0, value) of parameter TOUTPARA, as
!> Code_Aster's DEFI_CONSTANTE makes it. A FORMULE has no points (it is evaluated).
module function_points
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t, concept_display_name
    use tabulated_function, only: tabulated_function_t, PROL_EXCLU, PROL_CONSTANT, &
        PROL_LINEAIRE
    use constant_function, only: constant_function_t
    implicit none
    private

    !> NOM_PARA and NOM_RESU of a function that names none (Code_Aster's defaults).
    character(len=*), parameter, public :: CONSTANT_PARAMETER = 'TOUTPARA'
    character(len=*), parameter, public :: DEFAULT_RESULT_NAME = 'TOUTRESU'

    !> A function as points: abscissae, ordinates, names, prolongations.
    type, public :: function_samples_t
        real(dp), allocatable :: x(:), y(:)
        character(len=:), allocatable :: parameter, result_name
        integer :: left = PROL_EXCLU, right = PROL_EXCLU
    end type function_samples_t

    public :: samples_of_function, prolongation_name

contains

    !> The points of `f`.
    !>  st : STATUS_MODEL_ERROR for a formula or another concept (naming it)
    subroutine samples_of_function(f, samples, st)
        class(concept_t), intent(in) :: f
        type(function_samples_t), intent(out) :: samples
        type(status_t), intent(inout) :: st
        select type (f)
        type is (tabulated_function_t)
            samples%x = f%x
            samples%y = f%y
            samples%parameter = f%parameter
            samples%result_name = DEFAULT_RESULT_NAME
            if (allocated(f%result_name)) samples%result_name = f%result_name
            samples%left = f%left
            samples%right = f%right
        type is (constant_function_t)
            samples%x = [1.0_dp]
            samples%y = [f%value]
            samples%parameter = CONSTANT_PARAMETER
            samples%result_name = DEFAULT_RESULT_NAME
            if (allocated(f%result_name)) samples%result_name = f%result_name
            samples%left = PROL_CONSTANT
            samples%right = PROL_CONSTANT
        class default
            call set_error(st, STATUS_MODEL_ERROR, concept_display_name(f) // ' is a ' // &
                f%type_name() // ', not a function defined by points (DEFI_FONCTION, ' // &
                'DEFI_CONSTANTE, RECU_FONCTION, CALC_FONCTION)')
        end select
    end subroutine samples_of_function

    !> CONSTANT, LINEAIRE or EXCLU.
    pure function prolongation_name(code) result(name)
        integer, intent(in) :: code
        character(len=:), allocatable :: name
        select case (code)
        case (PROL_CONSTANT)
            name = 'CONSTANT'
        case (PROL_LINEAIRE)
            name = 'LINEAIRE'
        case default
            name = 'EXCLU'
        end select
    end function prolongation_name

end module function_points
