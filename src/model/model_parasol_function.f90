!> FONC_GROUP of RIGI_PARASOL: the coefficient of a raft cell is a function of the
!> distance from the cell centre to the centre point (Code_Aster U4.42.01, RIGI_PARASOL).
!> The function is evaluated through the function API (bind once, then evaluate).
module model_parasol_function
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use function_concept, only: function_concept_t, param_binding_t
    implicit none
    private

    !> Parameter name used to bind a function without parameters (a constant).
    character(len=*), parameter :: DISTANCE_NAME = 'R'

    public :: distance_function_values

contains

    !> values(i) = f(distances(i)). Whatever its parameter is called (NOM_PARA), the one
    !> parameter of f receives the distance; a constant (no parameter) is accepted.
    !>  f         : in, the FONC_GROUP function
    !>  distances : in, distances from the centre (one per raft cell)
    !>  values    : out, the coefficients
    !>  st        : out, STATUS_MODEL_ERROR when f has several parameters; the evaluation
    !>              errors of f (value outside an EXCLU range, math domain, ...)
    subroutine distance_function_values(f, distances, values, st)
        class(function_concept_t), intent(in) :: f
        real(dp), intent(in) :: distances(:)
        real(dp), allocatable, intent(out) :: values(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: params(:)
        type(param_binding_t) :: binding
        integer(i4) :: i
        allocate (values(size(distances)), source=0.0_dp)
        params = f%parameters()
        if (size(params) > 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'FONC_GROUP must be a function of one ' // &
                'parameter, the distance from the centre (this one has ' // &
                to_text(size(params, kind=i4)) // ')')
            return
        end if
        if (size(params) == 1) then
            call f%bind([params(1)%s], binding)
        else
            call f%bind([DISTANCE_NAME], binding)
        end if
        do i = 1, size(distances)
            call f%evaluate(binding, distances(i:i), values(i), st)
            if (st%failed()) return
        end do
    end subroutine distance_function_values

end module model_parasol_function
