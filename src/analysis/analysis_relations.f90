!> The linear relations of an analysis's loads (doc/analysis.md, "Linear relations"):
!> gathered from the EXCIT occurrences and eliminated before the equations are numbered
!> (prepare_relations), their slaves set at each instant from the masters, the imposed
!> values and the right-hand sides times FONC_MULT (relations_at). MECA_STATIQUE and
!> STAT_NON_LINE call both.
module analysis_relations
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use function_concept, only: param_binding_t
    use assembly_system, only: structure_t, assembly_map_t
    use assembly_relations, only: relation_rows_t, elimination_t, eliminate_relations, &
        apply_relations, has_relations
    use assembly_relation_loads, only: append_relation_rows, relation_rhs, mark_rigid_cells, &
        describe_row, locate_row
    use analysis_excitation, only: excitation_t
    implicit none
    private

    public :: prepare_relations, relations_at

contains

    !> The relations of every EXCIT load, eliminated, and the cells inside rigid bodies.
    !>  imposed : in, (n_equations) the imposed equations (they are never slaves)
    !>  elim    : out, for build_assembly_map
    !>  rigid   : out, (n_cells) cells inside a LIAISON_SOLIDE body
    !>  st      : out, a relation on a component no element carries; a relation that repeats
    !>            or contradicts the ones before it (a cycle of relations, a relation on
    !>            imposed components only ...): located at its occurrence, naming it
    subroutine prepare_relations(s, excit, imposed, elim, rigid, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        logical, intent(in) :: imposed(:)
        type(elimination_t), intent(out) :: elim
        logical, allocatable, intent(out) :: rigid(:)
        type(status_t), intent(out) :: st
        type(relation_rows_t) :: rows
        integer(i4) :: k, bad
        allocate (rigid(s%mesh%n_cells), source=.false.)
        do k = 1, size(excit, kind=i4)
            call append_relation_rows(s, excit(k)%load, k, rows, st)
            if (st%failed()) return
            call mark_rigid_cells(s, excit(k)%load, rigid)
        end do
        call eliminate_relations(rows, imposed, elim, bad, st)
        if (st%failed() .and. bad > 0) then
            associate (item => excit(elim%rows%load(bad))%load%items(elim%rows%item(bad)))
                call set_error(st, STATUS_MODEL_ERROR, 'the relation ' // &
                    describe_row(s, elim%rows, bad) // ' (relation ' // &
                    text_of(elim%rows%rel(bad)) // ' of the occurrence) ' // st%message // &
                    ': a cycle of relations, or a component both imposed and related to ' // &
                    'imposed ones only; Code_Aster''s dualised system would be singular ' // &
                    '(remove one of them)')
                call locate_row(item, st)
            end associate
        end if
    end subroutine prepare_relations

    !> Sets the slaves of u at time t (after the imposed values): u_s = sum c u_j + sum d
    !> beta, each relation's right-hand side times its EXCIT's FONC_MULT.
    !>  st : out, function evaluation errors (FONC_MULT, relation values), located
    subroutine relations_at(s, excit, map, t, u, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: t
        real(dp), intent(inout) :: u(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: beta(:)
        type(param_binding_t) :: binding
        real(dp) :: factor
        integer(i4) :: k
        if (.not. has_relations(map%elim)) return
        allocate (beta(map%elim%rows%n), source=0.0_dp)
        do k = 1, size(excit, kind=i4)
            if (.not. any(map%elim%rows%load == k)) cycle
            factor = 1.0_dp
            if (associated(excit(k)%fonc_mult)) then
                call excit(k)%fonc_mult%bind(['INST'], binding)
                call excit(k)%fonc_mult%evaluate(binding, [t], factor, st)
                if (st%failed()) then
                    call set_error(st, st%code, 'EXCIT/FONC_MULT: ' // st%message)
                    return
                end if
            end if
            call relation_rhs(s, excit(k)%load, k, map%elim%rows, t, factor, beta, st)
            if (st%failed()) return
        end do
        call apply_relations(map%elim, beta, u)
    end subroutine relations_at

    pure function text_of(i) result(text)
        integer(i4), intent(in) :: i
        character(len=:), allocatable :: text
        character(len=12) :: buf
        write (buf, '(i0)') i
        text = trim(buf)
    end function text_of

end module analysis_relations
