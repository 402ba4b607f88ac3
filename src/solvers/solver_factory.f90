!> Makes the direct solver a deck asks for (SOLVEUR/METHODE, U4.50.01) and checks its
!> RENUM: each method has its own orderings and default, as in Code_Aster.
!>   LDLT       : RCMK (default), METIS, SANS -- applied by the assembly (node order)
!>   MULT_FRONT : METIS (default), AMD, MD   -- CHOLMOD's ordering (MD runs AMD: CHOLMOD
!>                has no exact minimum degree)
!>   MUMPS      : AUTO (default), AMD, AMF, PORD, SCOTCH, QAMD -- MUMPS's ordering (ICNTL(7));
!>                SANS leaves MUMPS its automatic choice (as Code_Aster's driver does);
!>                Debian's MUMPS is built without METIS, so METIS is refused
!>   GCPC, PETSC: RCMK (default), SANS -- applied by the assembly (the incomplete factor's
!>                quality depends on it); the iterative methods are krylov_solver's
module solver_factory
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use direct_solver, only: direct_solver_t, solver_options_t
    use ldlt_solver, only: ldlt_solver_t
    use cholmod_solver, only: cholmod_solver_t
    use mumps_solver, only: mumps_solver_t
    use krylov_solver, only: krylov_solver_t
    implicit none
    private

    !> Code_Aster's default method (U4.50.01 SOLVEUR/METHODE).
    character(len=*), parameter, public :: DEFAULT_METHOD = 'MUMPS'

    public :: create_solver, default_renum, renum_allowed, assembly_renum

contains

    !> The default RENUM of a method ('' for an unknown method).
    pure function default_renum(method) result(renum)
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: renum
        select case (method)
        case ('LDLT')
            renum = 'RCMK'
        case ('MULT_FRONT')
            renum = 'METIS'
        case ('MUMPS')
            renum = 'AUTO'
        case ('GCPC', 'PETSC')
            renum = 'RCMK'
        case default
            renum = ''
        end select
    end function default_renum

    !> The orderings a method accepts, as a blank-separated list ('' if none).
    pure function renum_allowed(method) result(list)
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: list
        select case (method)
        case ('LDLT')
            list = 'RCMK METIS SANS'
        case ('MULT_FRONT')
            list = 'METIS AMD MD'
        case ('MUMPS')
            list = 'AUTO AMD AMF PORD SCOTCH QAMD SANS'
        case ('GCPC', 'PETSC')
            list = 'RCMK SANS'
        case default
            list = ''
        end select
    end function renum_allowed

    !> The node renumbering the assembly applies: RENUM for LDLT (the skyline has no
    !> ordering of its own) and the iterative methods, the mesh order ('SANS') for back-ends
    !> that order themselves.
    pure function assembly_renum(options) result(renum)
        type(solver_options_t), intent(in) :: options
        character(len=:), allocatable :: renum
        renum = 'SANS'
        select case (trim(options%method))
        case ('LDLT', 'GCPC', 'PETSC')
            renum = trim(options%renum)
            if (len(renum) == 0) renum = default_renum(trim(options%method))
        end select
    end function assembly_renum

    !> Allocates the back-end of options%method with its options (RENUM defaulted).
    !>  st : out, STATUS_DECK_ERROR for an unknown method or a RENUM it does not have
    !>       (the message lists the right ones)
    subroutine create_solver(options, solver, st)
        type(solver_options_t), intent(in) :: options
        class(direct_solver_t), allocatable, intent(out) :: solver
        type(status_t), intent(out) :: st
        type(solver_options_t) :: opt
        opt = options
        if (len_trim(opt%renum) == 0) opt%renum = default_renum(trim(opt%method))
        if (.not. word_in(trim(opt%renum), renum_allowed(trim(opt%method)))) then
            if (len(renum_allowed(trim(opt%method))) == 0) then
                call set_error(st, STATUS_DECK_ERROR, 'unknown METHODE ' // &
                    trim(opt%method) // ' (LDLT, MULT_FRONT, MUMPS, GCPC or PETSC)')
            else
                call set_error(st, STATUS_DECK_ERROR, 'RENUM ' // trim(opt%renum) // &
                    ' is not an ordering of METHODE ' // trim(opt%method) // ' (' // &
                    renum_allowed(trim(opt%method)) // ')')
            end if
            return
        end if
        select case (trim(opt%method))
        case ('LDLT')
            allocate (ldlt_solver_t :: solver)
        case ('MULT_FRONT')
            allocate (cholmod_solver_t :: solver)
        case ('GCPC', 'PETSC')
            allocate (krylov_solver_t :: solver)
        case default
            allocate (mumps_solver_t :: solver)
        end select
        solver%options = opt
    end subroutine create_solver

    pure logical function word_in(word, list)
        character(len=*), intent(in) :: word, list
        integer(i4) :: k
        k = index(' ' // list // ' ', ' ' // word // ' ')
        word_in = len(word) > 0 .and. k > 0
    end function word_in

end module solver_factory
