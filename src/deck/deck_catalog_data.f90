!> THE command catalog of parasol: every command of doc/deck-language.md with its keywords,
!> described once, as data (types, cardinality, defaults, allowed values, rules). Validation,
!> defaults and the documentation table all come from here. Defaults mirror Code_Aster's
!> (U4 documentation of each command); keywords marked noop are accepted so real decks run
!> unchanged, and have no effect in parasol. Each family of commands is described in a
!> module of its own (catalog_*.f90); this one gathers them.
module deck_catalog_data
    use deck_catalog, only: catalog_t
    use catalog_session, only: describe_session
    use catalog_mesh, only: describe_mesh_commands
    use catalog_mesh_model, only: describe_mesh_and_model
    use catalog_materials, only: describe_materials
    use catalog_cara_elem, only: describe_cara_elem
    use catalog_functions, only: describe_functions
    use catalog_loads, only: describe_loads
    use catalog_analyses, only: describe_analyses
    use catalog_list_inst, only: describe_list_inst
    use catalog_results, only: describe_outputs
    use catalog_fields, only: describe_fields
    use catalog_tables, only: describe_tables
    use catalog_result_functions, only: describe_result_functions
    implicit none
    private
    public :: build_catalog

contains

    !> Fills `cat` with every command.
    subroutine build_catalog(cat)
        type(catalog_t), intent(out) :: cat
        call describe_session(cat)
        call describe_mesh_commands(cat)
        call describe_mesh_and_model(cat)
        call describe_materials(cat)
        call describe_cara_elem(cat)
        call describe_functions(cat)
        call describe_loads(cat)
        call describe_analyses(cat)
        call describe_list_inst(cat)
        call describe_outputs(cat)
        call describe_fields(cat)
        call describe_tables(cat)
        call describe_result_functions(cat)
    end subroutine build_catalog

end module deck_catalog_data
