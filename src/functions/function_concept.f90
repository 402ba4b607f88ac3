!> The one evaluation API of every function concept (DEFI_CONSTANTE, DEFI_FONCTION,
!> FORMULE), for the load and element layers: bind the caller's parameter names ONCE, then
!> evaluate many times from a plain real array.
!>
!>     type(param_binding_t) :: b
!>     call pres%bind(['INST', 'X   ', 'Y   ', 'Z   '], b)
!>     do each Gauss point
!>         call pres%evaluate(b, [t, x, y, z], p, st)
!>         if (st%failed()) return          ! missing parameter, EXCLU range, math domain
!>     end do
!> Parameters the function does not use are ignored; a parameter it needs that the caller
!> did not name is an error at evaluation.
module function_concept
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t
    implicit none
    private

    !> For each parameter of the function, its index in the caller's value array (0 when
    !> the caller does not provide it).
    type, public :: param_binding_t
        integer, allocatable :: slot(:)
        type(string_t), allocatable :: names(:)      !< the function's parameter names
        type(string_t), allocatable :: provided(:)   !< the caller's names
    end type param_binding_t

    type, abstract, extends(concept_t), public :: function_concept_t
    contains
        procedure(function_parameters), deferred :: parameters
        procedure(function_evaluate), deferred :: evaluate
        procedure :: bind => function_bind
        procedure :: call_real => function_call_real
    end type function_concept_t

    abstract interface
        !> The function's parameter names (NOM_PARA), in call order.
        function function_parameters(self) result(names)
            import :: function_concept_t, string_t
            class(function_concept_t), intent(in) :: self
            type(string_t), allocatable :: names(:)
        end function function_parameters

        !> y = f(values) for a binding made by bind().
        !>  st : out, STATUS_MODEL_ERROR for a missing parameter, a value outside an EXCLU
        !>       range, a math domain error or overflow
        subroutine function_evaluate(self, binding, values, y, st)
            import :: function_concept_t, param_binding_t, dp, status_t
            class(function_concept_t), intent(in) :: self
            type(param_binding_t), intent(in) :: binding
            real(dp), intent(in) :: values(:)
            real(dp), intent(out) :: y
            type(status_t), intent(out) :: st
        end subroutine function_evaluate
    end interface

    public :: missing_parameter

contains

    !> Binds the caller's parameter names (e.g. ['INST','X','Y','Z'], blanks trimmed).
    subroutine function_bind(self, names, binding)
        class(function_concept_t), intent(in) :: self
        character(len=*), intent(in) :: names(:)
        type(param_binding_t), intent(out) :: binding
        integer :: k, j
        binding%names = self%parameters()
        allocate (binding%slot(size(binding%names)), binding%provided(size(names)))
        do j = 1, size(names)
            binding%provided(j)%s = trim(names(j))
        end do
        binding%slot = 0
        do k = 1, size(binding%names)
            do j = 1, size(names)
                if (trim(names(j)) == binding%names(k)%s) then
                    binding%slot(k) = j
                    exit
                end if
            end do
        end do
    end subroutine function_bind

    !> F(a, b, ...) in the deck: the arguments are the function's parameters, in order.
    recursive subroutine function_call_real(self, args, y, st)
        class(function_concept_t), intent(in) :: self
        real(dp), intent(in) :: args(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        type(param_binding_t) :: probe, binding
        character(len=64), allocatable :: given(:)
        integer :: k, n
        y = 0.0_dp
        call self%bind([character(len=1) :: ], probe)     ! learns the parameter names
        n = size(probe%names)
        if (n > 0 .and. size(args) /= n) then
            call set_error(st, STATUS_MODEL_ERROR, 'the function takes ' // to_text(n) // &
                           ' argument(s), got ' // to_text(size(args)))
            return
        end if
        allocate (given(size(args)))
        do k = 1, size(args)
            given(k) = ''
            if (k <= n) given(k) = probe%names(k)%s
        end do
        call self%bind(given, binding)
        call self%evaluate(binding, args, y, st)
    end subroutine function_call_real


    !> Sets the "parameter not provided" error for parameter k of a binding.
    subroutine missing_parameter(fname, binding, k, st)
        character(len=*), intent(in) :: fname
        type(param_binding_t), intent(in) :: binding
        integer, intent(in) :: k
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: have
        integer :: j
        have = ''
        do j = 1, size(binding%provided)
            if (j > 1) have = have // ', '
            have = have // binding%provided(j)%s
        end do
        call set_error(st, STATUS_MODEL_ERROR, 'function ' // fname // ' needs parameter ' // &
            binding%names(k)%s // ', which is not provided here (provided: ' // have // ')')
    end subroutine missing_parameter

end module function_concept
